<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="sk">
<context>
    <name>Main</name>
    <message>
        <source>Kontur</source>
        <translation>Kontur</translation>
    </message>
    <message>
        <source>New Bézier</source>
        <translation>Nová Bézierova krivka</translation>
    </message>
    <message>
        <source>Place 4 control points to make a cubic Bézier curve (B)</source>
        <translation>Umiestnite 4 kontrolné body a vytvorte kubickú Bézierovu krivku (B)</translation>
    </message>
    <message>
        <source>Move points</source>
        <translation>Posúvať body</translation>
    </message>
    <message>
        <source>Drag points to change curves; drag the canvas to pan (Esc)</source>
        <translation>Ťahaním bodov meníte krivky, ťahaním plátna posúvate pohľad (Esc)</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Späť</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Znova</translation>
    </message>
    <message>
        <source>Zoom out</source>
        <translation>Oddialiť</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>Zoom in</source>
        <translation>Priblížiť</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Prispôsobiť</translation>
    </message>
    <message>
        <source>Show all curves (F)</source>
        <translation>Zobraziť všetky krivky (F)</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Jazyk</translation>
    </message>
    <message>
        <source>Panel</source>
        <translation>Panel</translation>
    </message>
    <message>
        <source>New Bézier curve: tap or click control point %1 of %2. Esc cancels.</source>
        <translation>Nová Bézierova krivka: ťuknite alebo kliknite a umiestnite kontrolný bod %1 z %2. Esc zruší.</translation>
    </message>
    <message>
        <source>Press “New Bézier” and tap 4 points to draw your first curve.</source>
        <translation>Stlačte „Nová Bézierova krivka“ a ťuknutím zadajte 4 body svojej prvej krivky.</translation>
    </message>
    <message>
        <source>Drag a point to move it. Drag the canvas to pan; pinch or scroll to zoom.</source>
        <translation>Ťahaním bod posuniete. Ťahaním plátna posúvate pohľad; priblížite roztiahnutím dvoch prstov alebo kolieskom myši.</translation>
    </message>
</context>
<context>
    <name>SidePanel</name>
    <message>
        <source>Curves</source>
        <translation>Krivky</translation>
    </message>
    <message numerus="yes">
        <source>%1 · %2 · %n point(s)</source>
        <translation>
            <numerusform>%1 · %2 · %n bod</numerusform>
            <numerusform>%1 · %2 · %n body</numerusform>
            <numerusform>%1 · %2 · %n bodov</numerusform>
        </translation>
    </message>
    <message>
        <source>No curves yet.</source>
        <translation>Zatiaľ žiadne krivky.</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Body</translation>
    </message>
</context>
<context>
    <name>cli</name>
    <message>
        <source>Kontur: construct, modify and compare Bézier curves and splines.</source>
        <translation>Kontur: tvorba, úprava a porovnávanie Bézierových kriviek a splajnov.</translation>
    </message>
    <message>
        <source>Language of the user interface: %1.</source>
        <translation>Jazyk používateľského rozhrania: %1.</translation>
    </message>
    <message>
        <source>A Kontur document to open.</source>
        <translation>Dokument Kontur, ktorý sa má otvoriť.</translation>
    </message>
    <message>
        <source>kontur: unknown language &quot;%1&quot;; choose one of %2.</source>
        <translation>kontur: neznámy jazyk „%1“; vyberte jeden z: %2.</translation>
    </message>
    <message>
        <source>kontur: give at most one file to open.</source>
        <translation>kontur: zadajte najviac jeden súbor na otvorenie.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: no such file.</source>
        <translation>kontur: nedá sa otvoriť „%1“: taký súbor neexistuje.</translation>
    </message>
</context>
<context>
    <name>kontur</name>
    <message>
        <source>Add %1</source>
        <translation>Pridať %1</translation>
    </message>
    <message>
        <source>Move point</source>
        <translation>Posunúť bod</translation>
    </message>
    <message>
        <source>Bézier curve</source>
        <translation>Bézierova krivka</translation>
    </message>
    <message>
        <source>Bézier %1</source>
        <translation>Bézier %1</translation>
    </message>
    <message>
        <source>Opening documents is not available in this version yet: %1</source>
        <translation>Otváranie dokumentov v tejto verzii zatiaľ nie je k dispozícii: %1</translation>
    </message>
</context>
</TS>
