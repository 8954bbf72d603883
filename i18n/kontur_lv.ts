<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="lv">
<context>
    <name>Main</name>
    <message>
        <source>Kontur</source>
        <translation>Kontur</translation>
    </message>
    <message>
        <source>New Bézier</source>
        <translation>Jauna Bezjē līkne</translation>
    </message>
    <message>
        <source>Place 4 control points to make a cubic Bézier curve (B)</source>
        <translation>Novietojiet 4 kontrolpunktus, lai izveidotu kubisku Bezjē līkni (B)</translation>
    </message>
    <message>
        <source>Move points</source>
        <translation>Pārvietot punktus</translation>
    </message>
    <message>
        <source>Drag points to change curves; drag the canvas to pan (Esc)</source>
        <translation>Velciet punktus, lai mainītu līknes; velciet audeklu, lai pārvietotu skatu (Esc)</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Atsaukt</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Atcelt atsaukšanu</translation>
    </message>
    <message>
        <source>Zoom out</source>
        <translation>Attālināt</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>Zoom in</source>
        <translation>Pietuvināt</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Ietilpināt</translation>
    </message>
    <message>
        <source>Show all curves (F)</source>
        <translation>Rādīt visas līknes (F)</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Valoda</translation>
    </message>
    <message>
        <source>Panel</source>
        <translation>Panelis</translation>
    </message>
    <message>
        <source>New Bézier curve: tap or click control point %1 of %2. Esc cancels.</source>
        <translation>Jauna Bezjē līkne: pieskarieties vai noklikšķiniet, lai novietotu kontrolpunktu %1 no %2. Esc atceļ.</translation>
    </message>
    <message>
        <source>Press “New Bézier” and tap 4 points to draw your first curve.</source>
        <translation>Nospiediet “Jauna Bezjē līkne” un pieskarieties 4 punktiem, lai uzzīmētu pirmo līkni.</translation>
    </message>
    <message>
        <source>Drag a point to move it. Drag the canvas to pan; pinch or scroll to zoom.</source>
        <translation>Velciet punktu, lai to pārvietotu. Velciet audeklu, lai pārvietotu skatu; savelciet ar diviem pirkstiem vai ritiniet, lai tuvinātu vai tālinātu.</translation>
    </message>
</context>
<context>
    <name>SidePanel</name>
    <message>
        <source>Curves</source>
        <translation>Līknes</translation>
    </message>
    <message numerus="yes">
        <source>%1 · %2 · %n point(s)</source>
        <translation>
            <numerusform>%1 · %2 · %n punkts</numerusform>
            <numerusform>%1 · %2 · %n punkti</numerusform>
            <numerusform>%1 · %2 · %n punktu</numerusform>
        </translation>
    </message>
    <message>
        <source>No curves yet.</source>
        <translation>Vēl nav līkņu.</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Punkti</translation>
    </message>
</context>
<context>
    <name>cli</name>
    <message>
        <source>Kontur: construct, modify and compare Bézier curves and splines.</source>
        <translation>Kontur: Bezjē līkņu un splainu veidošana, mainīšana un salīdzināšana.</translation>
    </message>
    <message>
        <source>Language of the user interface: %1.</source>
        <translation>Lietotāja saskarnes valoda: %1.</translation>
    </message>
    <message>
        <source>A Kontur document to open.</source>
        <translation>Atveramais Kontur dokuments.</translation>
    </message>
    <message>
        <source>kontur: unknown language &quot;%1&quot;; choose one of %2.</source>
        <translation>kontur: nezināma valoda “%1”; izvēlieties kādu no: %2.</translation>
    </message>
    <message>
        <source>kontur: give at most one file to open.</source>
        <translation>kontur: norādiet ne vairāk kā vienu atveramo failu.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: no such file.</source>
        <translation>kontur: nevar atvērt “%1”: šāda faila nav.</translation>
    </message>
</context>
<context>
    <name>kontur</name>
    <message>
        <source>Add %1</source>
        <translation>Pievienot %1</translation>
    </message>
    <message>
        <source>Move point</source>
        <translation>Pārvietot punktu</translation>
    </message>
    <message>
        <source>Bézier curve</source>
        <translation>Bezjē līkne</translation>
    </message>
    <message>
        <source>Bézier %1</source>
        <translation>Bezjē %1</translation>
    </message>
    <message>
        <source>Opening documents is not available in this version yet: %1</source>
        <translation>Šajā versijā dokumentu atvēršana vēl nav pieejama: %1</translation>
    </message>
</context>
</TS>
