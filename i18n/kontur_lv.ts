<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="lv">
<context>
    <name>CanvasView</name>
    <message>
        <source>grid %1</source>
        <translation>režģis %1</translation>
    </message>
</context>
<context>
    <name>CoordinatesTable</name>
    <message>
        <source>OK</source>
        <translation>Labi</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Atiestatīt</translation>
    </message>
    <message>
        <source>Add row</source>
        <translation>Pievienot rindu</translation>
    </message>
    <message>
        <source>Delete row</source>
        <translation>Dzēst rindu</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>Kopēt</translation>
    </message>
</context>
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
        <source>Press “New Bézier” and tap 4 points to draw your first curve.</source>
        <translation>Nospiediet “Jauna Bezjē līkne” un pieskarieties 4 punktiem, lai uzzīmētu pirmo līkni.</translation>
    </message>
    <message>
        <source>Drag a point to move it. Drag the canvas to pan; pinch or scroll to zoom.</source>
        <translation>Velciet punktu, lai to pārvietotu. Velciet audeklu, lai pārvietotu skatu; savelciet ar diviem pirkstiem vai ritiniet, lai tuvinātu vai tālinātu.</translation>
    </message>
    <message>
        <source>New curve</source>
        <translation>Jauna līkne</translation>
    </message>
    <message>
        <source>Choose the kind of curve to place</source>
        <translation>Izvēlieties novietojamās līknes veidu</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>Gatavs</translation>
    </message>
    <message>
        <source>Finish the curve with the points placed so far (Enter)</source>
        <translation>Pabeigt līkni ar līdz šim novietotajiem punktiem (Enter)</translation>
    </message>
    <message>
        <source>Constrained</source>
        <translation>Ierobežoti</translation>
    </message>
    <message>
        <source>Composite handles keep their direction and change only their length (or drag with the right button or Shift)</source>
        <translation>Saliktas līknes rokturi saglabā virzienu un maina tikai garumu (vai velciet ar labo pogu vai Shift)</translation>
    </message>
    <message>
        <source>New curve: tap or click its points (%1 placed). Press Done to finish, Esc to cancel.</source>
        <translation>Jauna līkne: pieskarieties vai noklikšķiniet tās punktus (novietoti %1). Nospiediet “Gatavs”, lai pabeigtu, Esc — lai atceltu.</translation>
    </message>
    <message>
        <source>New curve: tap or click point %1 of %2. Esc cancels.</source>
        <translation>Jauna līkne: pieskarieties vai noklikšķiniet, lai novietotu punktu %1 no %2. Esc atceļ.</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Fails</translation>
    </message>
    <message>
        <source>New</source>
        <translation>Jauns</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Atvērt…</translation>
    </message>
    <message>
        <source>Open recent</source>
        <translation>Nesen atvērtie</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Saglabāt</translation>
    </message>
    <message>
        <source>Save as…</source>
        <translation>Saglabāt kā…</translation>
    </message>
    <message>
        <source>Import points, CSV or SVG…</source>
        <translation>Importēt punktus, CSV vai SVG…</translation>
    </message>
    <message>
        <source>Export SVG…</source>
        <translation>Eksportēt SVG…</translation>
    </message>
    <message>
        <source>Export the selected curve as CSV…</source>
        <translation>Eksportēt atlasīto līkni kā CSV…</translation>
    </message>
    <message>
        <source>Append the selected curve to a points file…</source>
        <translation>Pievienot atlasīto līkni punktu faila beigās…</translation>
    </message>
    <message>
        <source>Export PNG (view size)…</source>
        <translation>Eksportēt PNG (skata izmērā)…</translation>
    </message>
    <message>
        <source>Export PNG (2× view size)…</source>
        <translation>Eksportēt PNG (2× skata izmērā)…</translation>
    </message>
    <message>
        <source>Export PNG (4× view size)…</source>
        <translation>Eksportēt PNG (4× skata izmērā)…</translation>
    </message>
    <message>
        <source>Export PNG of the whole document (2×)…</source>
        <translation>Eksportēt visa dokumenta PNG (2×)…</translation>
    </message>
    <message>
        <source>Quit</source>
        <translation>Iziet</translation>
    </message>
    <message>
        <source>Grid</source>
        <translation>Režģis</translation>
    </message>
    <message>
        <source>Show or hide the grid and the axes (G)</source>
        <translation>Rādīt vai slēpt režģi un asis (G)</translation>
    </message>
    <message>
        <source>Reset all</source>
        <translation>Atiestatīt visu</translation>
    </message>
    <message>
        <source>Close message</source>
        <translation>Aizvērt ziņojumu</translation>
    </message>
    <message>
        <source>Kontur documents (*.kontur)</source>
        <translation>Kontur dokumenti (*.kontur)</translation>
    </message>
    <message>
        <source>Points, CSV and SVG files (*.txt *.csv *.svg)</source>
        <translation>Punktu, CSV un SVG faili (*.txt *.csv *.svg)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Visi faili (*)</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Atvērt</translation>
    </message>
    <message>
        <source>Save as</source>
        <translation>Saglabāt kā</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Importēt</translation>
    </message>
    <message>
        <source>Points, CSV, SVG and Kontur files (*.txt *.csv *.svg *.kontur)</source>
        <translation>Punktu, CSV, SVG un Kontur faili (*.txt *.csv *.svg *.kontur)</translation>
    </message>
    <message>
        <source>Export SVG</source>
        <translation>Eksportēt SVG</translation>
    </message>
    <message>
        <source>SVG images (*.svg)</source>
        <translation>SVG attēli (*.svg)</translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation>Eksportēt CSV</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV faili (*.csv)</translation>
    </message>
    <message>
        <source>Append to a points file</source>
        <translation>Pievienot punktu faila beigās</translation>
    </message>
    <message>
        <source>Points files (*.txt)</source>
        <translation>Punktu faili (*.txt)</translation>
    </message>
    <message>
        <source>Export PNG</source>
        <translation>Eksportēt PNG</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG attēli (*.png)</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Nesaglabātas izmaiņas</translation>
    </message>
    <message>
        <source>“%1” has changes that are not saved. Save them first?</source>
        <translation>Dokumentā “%1” ir nesaglabātas izmaiņas. Vai vispirms tās saglabāt?</translation>
    </message>
    <message>
        <source>Recover unsaved work</source>
        <translation>Atjaunot nesaglabāto darbu</translation>
    </message>
    <message>
        <source>Kontur was not closed properly last time. Recover the unsaved work?</source>
        <translation>Iepriekšējā reizē Kontur netika pareizi aizvērts. Vai atjaunot nesaglabāto darbu?</translation>
    </message>
    <message>
        <source>Load background image</source>
        <translation>Ielādēt fona attēlu</translation>
    </message>
    <message>
        <source>Images (*.png *.jpg *.jpeg *.bmp *.gif *.webp)</source>
        <translation>Attēli (*.png *.jpg *.jpeg *.bmp *.gif *.webp)</translation>
    </message>
</context>
<context>
    <name>SidePanel</name>
    <message>
        <source>Curves</source>
        <translation>Līknes</translation>
    </message>
    <message>
        <source>No curves yet.</source>
        <translation>Vēl nav līkņu.</translation>
    </message>
    <message>
        <source>%1 · cannot be drawn from these points</source>
        <translation>%1 · no šiem punktiem nevar uzzīmēt</translation>
    </message>
    <message numerus="yes">
        <source>%1 · %n point(s) · length %2</source>
        <translation>
            <numerusform>%1 · %n punkts · garums %2</numerusform>
            <numerusform>%1 · %n punkti · garums %2</numerusform>
            <numerusform>%1 · %n punktu · garums %2</numerusform>
        </translation>
    </message>
    <message>
        <source>Selected curve</source>
        <translation>Atlasītā līkne</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nosaukums</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Veids</translation>
    </message>
    <message>
        <source>degree %1</source>
        <translation>pakāpe %1</translation>
    </message>
    <message>
        <source>Parameterization</source>
        <translation>Parametrizācija</translation>
    </message>
    <message>
        <source>Uniform</source>
        <translation>Vienmērīgā sadalījuma</translation>
    </message>
    <message>
        <source>Chord length</source>
        <translation>Hordu garuma</translation>
    </message>
    <message>
        <source>Centripetal</source>
        <translation>Centrtieces spēka</translation>
    </message>
    <message>
        <source>Order</source>
        <translation>Kārta</translation>
    </message>
    <message>
        <source>Node type</source>
        <translation>Mezgla veids</translation>
    </message>
    <message>
        <source>Smooth</source>
        <translation>Gluds</translation>
    </message>
    <message>
        <source>Symmetric</source>
        <translation>Simetrisks</translation>
    </message>
    <message>
        <source>Corner</source>
        <translation>Stūra</translation>
    </message>
    <message>
        <source>Colour</source>
        <translation>Krāsa</translation>
    </message>
    <message>
        <source>Visible</source>
        <translation>Redzama</translation>
    </message>
    <message>
        <source>Locked</source>
        <translation>Bloķēta</translation>
    </message>
    <message>
        <source>Close curve</source>
        <translation>Noslēgt līkni</translation>
    </message>
    <message>
        <source>Move up</source>
        <translation>Pārvietot augšup</translation>
    </message>
    <message>
        <source>Move down</source>
        <translation>Pārvietot lejup</translation>
    </message>
    <message>
        <source>Delete curve</source>
        <translation>Dzēst līkni</translation>
    </message>
    <message>
        <source>Coordinates</source>
        <translation>Koordinātas</translation>
    </message>
    <message>
        <source>Info</source>
        <translation>Informācija</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Garums</translation>
    </message>
    <message>
        <source>Fit error (RMS / max)</source>
        <translation>Aproksimācijas kļūda (RMS / maks.)</translation>
    </message>
    <message>
        <source>Continuity</source>
        <translation>Nepārtrauktība</translation>
    </message>
    <message>
        <source>joint %1: %2</source>
        <translation>savienojums %1: %2</translation>
    </message>
    <message>
        <source>Background image</source>
        <translation>Fona attēls</translation>
    </message>
    <message>
        <source>Load image…</source>
        <translation>Ielādēt attēlu…</translation>
    </message>
    <message>
        <source>Show background</source>
        <translation>Rādīt fonu</translation>
    </message>
    <message>
        <source>Opacity</source>
        <translation>Necaurredzamība</translation>
    </message>
    <message>
        <source>Remove background</source>
        <translation>Noņemt fonu</translation>
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
        <source>Delete %1</source>
        <translation>Dzēst %1</translation>
    </message>
    <message>
        <source>Reorder curves</source>
        <translation>Mainīt līkņu secību</translation>
    </message>
    <message>
        <source>Change background</source>
        <translation>Mainīt fona attēlu</translation>
    </message>
    <message>
        <source>Cubic through 4 points</source>
        <translation>Kubiska līkne caur 4 punktiem</translation>
    </message>
    <message>
        <source>Least-squares cubic</source>
        <translation>Mazāko kvadrātu kubiskā līkne</translation>
    </message>
    <message>
        <source>Composite curve</source>
        <translation>Salikta līkne</translation>
    </message>
    <message>
        <source>Through 4 points %1</source>
        <translation>Caur 4 punktiem %1</translation>
    </message>
    <message>
        <source>Least squares %1</source>
        <translation>Mazākie kvadrāti %1</translation>
    </message>
    <message>
        <source>Composite %1</source>
        <translation>Salikta %1</translation>
    </message>
    <message>
        <source>Change parameterization</source>
        <translation>Mainīt parametrizāciju</translation>
    </message>
    <message>
        <source>Rename curve</source>
        <translation>Pārdēvēt līkni</translation>
    </message>
    <message>
        <source>Change colour</source>
        <translation>Mainīt krāsu</translation>
    </message>
    <message>
        <source>Show curve</source>
        <translation>Rādīt līkni</translation>
    </message>
    <message>
        <source>Hide curve</source>
        <translation>Paslēpt līkni</translation>
    </message>
    <message>
        <source>Lock curve</source>
        <translation>Bloķēt līkni</translation>
    </message>
    <message>
        <source>Unlock curve</source>
        <translation>Atbloķēt līkni</translation>
    </message>
    <message>
        <source>Change node type</source>
        <translation>Mainīt mezgla veidu</translation>
    </message>
    <message>
        <source>Add point</source>
        <translation>Pievienot punktu</translation>
    </message>
    <message>
        <source>Delete point</source>
        <translation>Dzēst punktu</translation>
    </message>
    <message>
        <source>Insert knot</source>
        <translation>Ievietot mezgla punktu</translation>
    </message>
    <message>
        <source>Close curve</source>
        <translation>Noslēgt līkni</translation>
    </message>
    <message>
        <source>Edit coordinates</source>
        <translation>Labot koordinātas</translation>
    </message>
    <message>
        <source>Reset all</source>
        <translation>Atiestatīt visu</translation>
    </message>
    <message>
        <source>Natural spline</source>
        <translation>Dabiskais splains</translation>
    </message>
    <message>
        <source>Clamped spline</source>
        <translation>Nostiprināts splains</translation>
    </message>
    <message>
        <source>Not-a-knot spline</source>
        <translation>Splains ar not-a-knot nosacījumu</translation>
    </message>
    <message>
        <source>Periodic spline</source>
        <translation>Periodisks splains</translation>
    </message>
    <message>
        <source>Catmull–Rom spline</source>
        <translation>Katmula–Roma splains</translation>
    </message>
    <message>
        <source>Hermite spline</source>
        <translation>Ermita splains</translation>
    </message>
    <message>
        <source>B-spline</source>
        <translation>B-splains</translation>
    </message>
    <message>
        <source>Global B-spline</source>
        <translation>Globālais B-splains</translation>
    </message>
    <message>
        <source>Interpolating polynomial</source>
        <translation>Interpolācijas polinoms</translation>
    </message>
    <message>
        <source>Function spline y(x)</source>
        <translation>Funkcijas splains y(x)</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>Change order</source>
        <translation>Mainīt splaina kārtu</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Bez nosaukuma</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Importēt %1</translation>
    </message>
</context>
<context>
    <name>messages</name>
    <message>
        <source>File upload error!</source>
        <translation>Faila augšupielādes kļūda!</translation>
    </message>
    <message>
        <source>The .txt file was not correct!</source>
        <translation>.txt fails nebija pareizs!</translation>
    </message>
    <message>
        <source>Output error!</source>
        <translation>Izvades kļūda!</translation>
    </message>
    <message>
        <source>Do you want to reset everything? All curves will be removed.</source>
        <translation>Vai vēlaties visu atiestatīt? Visas līknes tiks noņemtas.</translation>
    </message>
    <message>
        <source>Not allowed to move control points of a %1: move its knots.</source>
        <translation>Nav atļauts pārvietot līknes “%1” kontrolpunktus: pārvietojiet tās mezgla punktus.</translation>
    </message>
    <message>
        <source>Not allowed to move control points of a composite curve by keyboard!</source>
        <translation>Nav atļauts pārvietot saliktas līknes kontrolpunktus ar tastatūru!</translation>
    </message>
    <message>
        <source>A %1 does not use a parameterization.</source>
        <translation>Līkne “%1” neizmanto parametrizāciju.</translation>
    </message>
    <message>
        <source>The maximum count of points is %1!</source>
        <translation>Maksimālais punktu skaits ir %1!</translation>
    </message>
    <message>
        <source>A %1 can not have less than %2 points!</source>
        <translation>Līknei “%1” nevar būt mazāk par %2 punktiem!</translation>
    </message>
    <message>
        <source>Must fill all values with numbers!</source>
        <translation>Visas vērtības jāaizpilda ar skaitļiem!</translation>
    </message>
    <message>
        <source>“%1” is locked: unlock it to change it.</source>
        <translation>“%1” ir bloķēta: atbloķējiet to, lai mainītu.</translation>
    </message>
    <message>
        <source>The knots of this %1 do not define a curve: they need at least 4 different positions.</source>
        <translation>Šīs līknes “%1” mezgla punkti nenosaka līkni: vajag vismaz 4 dažādas vietas.</translation>
    </message>
    <message>
        <source>This is not possible for a %1.</source>
        <translation>Līknei “%1” tas nav iespējams.</translation>
    </message>
    <message>
        <source>Could not read “%1”: %2</source>
        <translation>Nevarēja nolasīt failu “%1”: %2</translation>
    </message>
    <message>
        <source>Could not write “%1”: %2. The file was left as it was.</source>
        <translation>Nevarēja ierakstīt failā “%1”: %2. Fails netika mainīts.</translation>
    </message>
    <message numerus="yes">
        <source>%n curve(s) read from “%1”.</source>
        <translation>
            <numerusform>No faila “%1” nolasīta %n līkne.</numerusform>
            <numerusform>No faila “%1” nolasītas %n līknes.</numerusform>
            <numerusform>No faila “%1” nolasīts %n līkņu.</numerusform>
        </translation>
    </message>
    <message>
        <source>Saved “%1”.</source>
        <translation>Fails “%1” saglabāts.</translation>
    </message>
</context>
</TS>
