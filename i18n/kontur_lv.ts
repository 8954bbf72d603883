<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="lv">
<context>
    <name>AppActions</name>
    <message>
        <source>File</source>
        <extracomment>Menu title (noun): the file commands.</extracomment>
        <translation>Fails</translation>
    </message>
    <message>
        <source>New, open, save, import and export</source>
        <translation>Izveidot, atvērt, saglabāt, importēt un eksportēt</translation>
    </message>
    <message>
        <source>Open %1</source>
        <translation>Atvērt %1</translation>
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
        <source>New Bézier</source>
        <extracomment>Tool-bar button, short for “New Bézier curve”: starts placing the control points of a new Bézier curve.</extracomment>
        <translatorcomment>The full name (Bezjē līkne): Bezjē alone cannot stand for the curve in Latvian.</translatorcomment>
        <translation>Jauna Bezjē līkne</translation>
    </message>
    <message>
        <source>Place 4 control points to make a cubic Bézier curve (B)</source>
        <translation>Novietojiet 4 kontrolpunktus, lai izveidotu kubisku Bezjē līkni (B)</translation>
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
        <extracomment>Button: finishes the curve being placed (keeps the points placed so far).</extracomment>
        <translation>Gatavs</translation>
    </message>
    <message>
        <source>Finish the curve with the points placed so far (Enter)</source>
        <translation>Pabeigt līkni ar līdz šim novietotajiem punktiem (Enter)</translation>
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
        <source>Constrained handles</source>
        <translation>Ierobežoti rokturi</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Atsaukt</translation>
    </message>
    <message>
        <source>Undo (Ctrl+Z)</source>
        <translation>Atsaukt (Ctrl+Z)</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Atkārtot</translation>
    </message>
    <message>
        <source>Redo (Ctrl+Shift+Z)</source>
        <translation>Atcelt atsaukšanu (Ctrl+Shift+Z)</translation>
    </message>
    <message>
        <source>Reset all</source>
        <translation>Notīrīt visu</translation>
    </message>
    <message>
        <source>Remove every curve and the background picture</source>
        <translation>Noņemt visas līknes un fona attēlu</translation>
    </message>
    <message>
        <source>Teaching</source>
        <extracomment>Menu title (noun): the teaching views (de Casteljau, degree elevation, basis functions…).</extracomment>
        <translation>Mācības</translation>
    </message>
    <message>
        <source>Views that show how curves are built</source>
        <translation>Skati, kas rāda, kā veidojas līknes</translation>
    </message>
    <message>
        <source>de Casteljau construction</source>
        <translation>de Casteljau konstrukcija</translation>
    </message>
    <message>
        <source>Degree elevation</source>
        <translation>Pakāpes paaugstināšana</translation>
    </message>
    <message>
        <source>Compare curve kinds</source>
        <translation>Salīdzināt līkņu veidus</translation>
    </message>
    <message>
        <source>Curvature comb and continuity</source>
        <translation>Liekuma ķemme un nepārtrauktība</translation>
    </message>
    <message>
        <source>Basis functions</source>
        <translation>Bāzes funkcijas</translation>
    </message>
    <message>
        <source>Function spline y(x)…</source>
        <translation>Funkcijas splains y(x)…</translation>
    </message>
    <message>
        <source>Runge phenomenon: comparison…</source>
        <translation>Runges fenomens: salīdzinājums…</translation>
    </message>
    <message>
        <source>Cubic segments with guide vectors…</source>
        <translation>Kubiskie segmenti ar virziena vektoriem…</translation>
    </message>
    <message>
        <source>Presentation mode (F5)</source>
        <translation>Prezentācijas režīms (F5)</translation>
    </message>
    <message>
        <source>Trace</source>
        <extracomment>Menu title: the tools for tracing a pattern from a photo; a title, not an order.</extracomment>
        <translation>Pārzīmēt</translation>
    </message>
    <message>
        <source>Trace a pattern: freehand, calibrate, measure, compare</source>
        <translation>Pārzīmēt piegrieztni: ar brīvu roku, kalibrēt, mērīt, salīdzināt</translation>
    </message>
    <message>
        <source>Freehand (T)</source>
        <translation>Ar brīvu roku (T)</translation>
    </message>
    <message>
        <source>Calibrate background (K)</source>
        <translation>Kalibrēt fonu (K)</translation>
    </message>
    <message>
        <source>Measure distance (M)</source>
        <translation>Mērīt attālumu (M)</translation>
    </message>
    <message>
        <source>Seam length between knots (L)</source>
        <translation>Šuves garums starp mezgla punktiem (L)</translation>
    </message>
    <message>
        <source>Move background (O)</source>
        <translation>Pārvietot fonu (O)</translation>
    </message>
    <message>
        <source>Snap to knots, grid and marks (S)</source>
        <translation>Piesaistīt mezgla punktiem, režģim un atzīmēm (S)</translation>
    </message>
    <message>
        <source>Lock background</source>
        <translation>Bloķēt fonu</translation>
    </message>
    <message>
        <source>Zoom in</source>
        <translation>Pietuvināt</translation>
    </message>
    <message>
        <source>Zoom in (+)</source>
        <translation>Pietuvināt (+)</translation>
    </message>
    <message>
        <source>Zoom out</source>
        <translation>Attālināt</translation>
    </message>
    <message>
        <source>Zoom out (−)</source>
        <translation>Attālināt (−)</translation>
    </message>
    <message>
        <source>Fit to view</source>
        <extracomment>Command: zoom so that all curves fit in the window.</extracomment>
        <translation>Ietilpināt skatā</translation>
    </message>
    <message>
        <source>Show all curves (F)</source>
        <translation>Rādīt visas līknes (F)</translation>
    </message>
    <message>
        <source>Grid</source>
        <extracomment>Toggle (noun): show or hide the grid on the canvas.</extracomment>
        <translation>Režģis</translation>
    </message>
    <message>
        <source>Show or hide the grid and the axes (G)</source>
        <translation>Rādīt vai slēpt režģi un asis (G)</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Valoda</translation>
    </message>
    <message>
        <source>Side panel</source>
        <translation>Sānu panelis</translation>
    </message>
    <message>
        <source>Show or hide the side panel: the curves, their points and settings</source>
        <translation>Rādīt vai slēpt sānu paneli: līknes, to punktus un iestatījumus</translation>
    </message>
    <message>
        <source>Seam allowance…</source>
        <translation>Šuves pielaide…</translation>
    </message>
    <message>
        <source>Calibrate perspective (Shift+K)</source>
        <translation>Kalibrēt perspektīvu (Shift+K)</translation>
    </message>
    <message>
        <source>Make line</source>
        <translation>Iztaisnot segmentu</translation>
    </message>
    <message>
        <source>Make the selected segment a straight line; its knots become corners (Shift+L)</source>
        <translation>Pārvērst atlasīto segmentu taisnā līnijā; tā mezgla punkti kļūst par stūra mezgla punktiem (Shift+L)</translation>
    </message>
    <message>
        <source>Delete knot</source>
        <translation>Dzēst mezgla punktu</translation>
    </message>
    <message>
        <source>Delete the selected knot; its two segments become one</source>
        <translation>Dzēst atlasīto mezgla punktu; tā divi segmenti kļūst par vienu</translation>
    </message>
    <message>
        <source>Smooth knot</source>
        <translation>Gluds mezgla punkts</translation>
    </message>
    <message>
        <source>The handles of the selected knot stay on one line (Shift+S)</source>
        <translation>Atlasītā mezgla punkta rokturi paliek uz vienas taisnes (Shift+S)</translation>
    </message>
    <message>
        <source>Symmetric knot</source>
        <translation>Simetrisks mezgla punkts</translation>
    </message>
    <message>
        <source>The handles of the selected knot mirror each other (Shift+Y)</source>
        <translation>Atlasītā mezgla punkta rokturi ir viens otra spoguļattēls (Shift+Y)</translation>
    </message>
    <message>
        <source>Corner knot</source>
        <translation>Stūra mezgla punkts</translation>
    </message>
    <message>
        <source>The handles of the selected knot move independently (Shift+C)</source>
        <translation>Atlasītā mezgla punkta rokturi pārvietojas neatkarīgi (Shift+C)</translation>
    </message>
    <message>
        <source>Close curve</source>
        <translation>Noslēgt līkni</translation>
    </message>
    <message>
        <source>Join the curve&apos;s last knot to its first; ends that meet become one knot (Shift+O)</source>
        <translation>Savienot līknes pēdējo mezgla punktu ar pirmo; gali, kas sakrīt, kļūst par vienu mezgla punktu (Shift+O)</translation>
    </message>
    <message>
        <source>Join curves</source>
        <translation>Savienot līknes</translation>
    </message>
    <message>
        <source>Join the selected curve with the curve whose end is nearest to one of its ends (Shift+J)</source>
        <translation>Savienot atlasīto līkni ar līkni, kuras gals ir vistuvāk kādam no tās galiem (Shift+J)</translation>
    </message>
    <message>
        <source>Simplify curve…</source>
        <translation>Vienkāršot līkni…</translation>
    </message>
    <message>
        <source>Fewer knots within a tolerance you type</source>
        <translation>Mazāk mezgla punktu, ievērojot jūsu ievadīto precizitāti</translation>
    </message>
    <message>
        <source>Trace outline</source>
        <translation>Pārzīmēt kontūru</translation>
    </message>
    <message>
        <source>The handles of composite curves keep their direction and change only their length (or drag with the right button or Shift)</source>
        <translation>Salikto līkņu rokturi saglabā virzienu un maina tikai garumu (vai velciet ar labo peles pogu vai ar nospiestu Shift)</translation>
    </message>
    <message>
        <source>Deviation from a reference curve (D)</source>
        <translation>Novirze no etalonlīknes (D)</translation>
    </message>
</context>
<context>
    <name>AppToolBar</name>
    <message>
        <source>%1 %</source>
        <extracomment>Zoom as a percentage: %1 is a number (150 → “150 %”); write the percent sign as your language does.</extracomment>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>Zoom %1</source>
        <extracomment>Screen-reader name: %1 is the zoom percentage, for example “150 %”.</extracomment>
        <translation>Tālummaiņa %1</translation>
    </message>
    <message>
        <source>More</source>
        <extracomment>Tool-bar button that opens a menu with the commands that do not fit on the bar.</extracomment>
        <translation>Vairāk</translation>
    </message>
    <message>
        <source>More commands</source>
        <translation>Citas komandas</translation>
    </message>
</context>
<context>
    <name>BasisPlot</name>
    <message numerus="yes">
        <source>Too many basis functions to draw (%n).</source>
        <translation>
            <numerusform>Pārāk daudz bāzes funkciju, lai tās uzzīmētu (%n).</numerusform>
            <numerusform>Pārāk daudz bāzes funkciju, lai tās uzzīmētu (%n).</numerusform>
            <numerusform>Pārāk daudz bāzes funkciju, lai tās uzzīmētu (%n).</numerusform>
        </translation>
    </message>
    <message>
        <source>Bernstein polynomials of degree %1</source>
        <translation>%1. pakāpes Bernšteina polinomi</translation>
    </message>
    <message>
        <source>B-spline basis functions N(i,k), order k = %1</source>
        <translation>B-splaina bāzes funkcijas N(i,k), kārta k = %1</translation>
    </message>
    <message>
        <source>Bell functions Bs of degree %1</source>
        <extracomment>Title: the bell-shaped B-spline basis functions Bs (one bell per knot) of degree %1 (a number).</extracomment>
        <translation>%1. pakāpes zvanveida funkcijas Bs</translation>
    </message>
    <message>
        <source>Hermite basis functions on one segment</source>
        <translation>Ermita bāzes funkcijas vienā segmentā</translation>
    </message>
    <message>
        <source>Knot vector: %1</source>
        <translation>Mezglu vektors: %1</translation>
    </message>
    <message>
        <source> (sum %1)</source>
        <translation> (summa %1)</translation>
    </message>
    <message numerus="yes">
        <source>Hermite basis functions on the curve&apos;s %n segment(s)</source>
        <translation>
            <numerusform>Ermita bāzes funkcijas līknes %n segmentā</numerusform>
            <numerusform>Ermita bāzes funkcijas līknes %n segmentos</numerusform>
            <numerusform>Ermita bāzes funkcijas līknes %n segmentos</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>BasisPlotPanel</name>
    <message>
        <source>Collapse the basis functions</source>
        <translation>Sakļaut bāzes funkcijas</translation>
    </message>
    <message>
        <source>Expand the basis functions</source>
        <translation>Izvērst bāzes funkcijas</translation>
    </message>
    <message>
        <source>Of the selected curve</source>
        <extracomment>Choices of the basis functions plotted: the selected curve&apos;s own, or a family named with its basis.</extracomment>
        <translation>Atlasītās līknes</translation>
    </message>
    <message>
        <source>B-spline</source>
        <translation>B-splains</translation>
    </message>
    <message>
        <source>Bell functions</source>
        <translation>Zvanveida funkcijas</translation>
    </message>
    <message>
        <source>Basis functions</source>
        <translation>Bāzes funkcijas</translation>
    </message>
    <message>
        <source>Degree</source>
        <translation>Pakāpe</translation>
    </message>
    <message>
        <source>Order</source>
        <extracomment>Label (noun): the order k of the B-spline basis functions (degree + 1), a number.</extracomment>
        <translation>Kārta</translation>
    </message>
    <message>
        <source>Functions</source>
        <extracomment>Label (noun): how many basis functions are drawn (a number beside it).</extracomment>
        <translation>Funkcijas</translation>
    </message>
    <message>
        <source>Number of basis functions</source>
        <translation>Bāzes funkciju skaits</translation>
    </message>
    <message>
        <source>Close the basis functions</source>
        <translation>Aizvērt bāzes funkcijas</translation>
    </message>
    <message>
        <source>Plot of the basis functions; the left and right arrow keys move t</source>
        <translation>Bāzes funkciju grafiks; kreisais un labais bulttaustiņš maina t</translation>
    </message>
    <message>
        <source>Bernstein basis</source>
        <translation>Bernšteina bāze</translation>
    </message>
    <message>
        <source>Hermite basis</source>
        <translation>Ermita bāze</translation>
    </message>
    <message>
        <source>Make the basis functions smaller</source>
        <translation>Samazināt bāzes funkcijas</translation>
    </message>
    <message>
        <source>Enlarge the basis functions</source>
        <translation>Palielināt bāzes funkcijas</translation>
    </message>
</context>
<context>
    <name>BottomSheet</name>
    <message>
        <source>Panel size: tap to show more, drag to resize</source>
        <translation>Paneļa augstums: pieskarieties, lai redzētu vairāk, velciet, lai mainītu augstumu</translation>
    </message>
</context>
<context>
    <name>CanvasView</name>
    <message>
        <source>grid %1</source>
        <extracomment>%1 is the grid spacing in the document&apos;s units (a number).</extracomment>
        <translation>režģis %1</translation>
    </message>
</context>
<context>
    <name>ConfirmDialog</name>
    <message>
        <source>Yes</source>
        <translation>Jā</translation>
    </message>
    <message>
        <source>No</source>
        <translation>Nē</translation>
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
        <extracomment>Button: throws away the values typed in the table; the curve stays as it was.</extracomment>
        <translation>Atmest izmaiņas</translation>
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
    <name>FileActions</name>
    <message>
        <source>New</source>
        <extracomment>Command (verb/adjective): start a new, empty document.</extracomment>
        <translation>Jauns</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Atvērt…</translation>
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
        <source>Kontur documents (*.kontur)</source>
        <translation>Kontur dokumenti (*.kontur)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Visi faili (*)</translation>
    </message>
    <message>
        <source>Open</source>
        <extracomment>Title of the file dialog that opens a document (verb: open a file).</extracomment>
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
        <source>Load background image</source>
        <translation>Ielādēt fona attēlu</translation>
    </message>
    <message>
        <source>Images (*.png *.jpg *.jpeg *.heic *.heif *.bmp *.gif *.webp)</source>
        <translation>Attēli (*.png *.jpg *.jpeg *.heic *.heif *.bmp *.gif *.webp)</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Nesaglabātas izmaiņas</translation>
    </message>
    <message>
        <source>“%1” has changes that are not saved. Save them first?</source>
        <translatorcomment>„…“ kept deliberately as the house style for quotation marks (as in Latvian legislation and school books); used the same way in every message.</translatorcomment>
        <translation>Dokumentā „%1“ ir nesaglabātas izmaiņas. Vai vispirms tās saglabāt?</translation>
    </message>
    <message>
        <source>Don’t save</source>
        <translation>Nesaglabāt</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Atcelt</translation>
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
        <source>Recover</source>
        <translation>Atjaunot</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Atmest</translation>
    </message>
    <message>
        <source>Print pattern…</source>
        <translation>Drukāt piegrieztni…</translation>
    </message>
    <message>
        <source>Print pattern to PDF</source>
        <translation>Drukāt piegrieztni PDF failā</translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation>PDF faili (*.pdf)</translation>
    </message>
    <message>
        <source>Kontur documents and printed patterns (%1)</source>
        <translation>Kontur dokumenti un izdrukātas piegrieztnes (%1)</translation>
    </message>
    <message>
        <source>Import points, CSV, SVG or DXF…</source>
        <translation>Importēt punktus, CSV, SVG vai DXF…</translation>
    </message>
    <message>
        <source>Export DXF with splines…</source>
        <translation>Eksportēt DXF ar splainiem…</translation>
    </message>
    <message>
        <source>The exact curves as DXF splines, in the document&apos;s units, for CAD and pattern software</source>
        <translation>Precīzas līknes kā DXF splaini dokumenta mērvienībās — CAD un piegrieztņu programmām</translation>
    </message>
    <message>
        <source>Export DXF with polylines…</source>
        <translation>Eksportēt DXF ar lauztām līnijām…</translation>
    </message>
    <message>
        <source>The curves as DXF polylines within 0.05 mm, for plotters and cutters without splines</source>
        <translation>Līknes kā DXF lauztas līnijas ar precizitāti 0,05 mm — ploteriem un griešanas iekārtām bez splainiem</translation>
    </message>
    <message>
        <source>Points, CSV, SVG and DXF files (%1)</source>
        <translation>Punktu, CSV, SVG un DXF faili (%1)</translation>
    </message>
    <message>
        <source>Points, CSV, SVG, DXF, Kontur files and printed patterns (%1)</source>
        <translation>Punktu, CSV, SVG, DXF, Kontur faili un izdrukātas piegrieztnes (%1)</translation>
    </message>
    <message>
        <source>Export DXF</source>
        <translation>Eksportēt DXF</translation>
    </message>
    <message>
        <source>DXF drawings (*.dxf)</source>
        <translation>DXF rasējumi (*.dxf)</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Eksportēt</translation>
    </message>
    <message>
        <source>Append</source>
        <translation>Pievienot</translation>
    </message>
    <message>
        <source>Export DXF for pattern software (AAMA)…</source>
        <extracomment>AAMA (ASTM D6673) is the DXF that garment pattern software and cutters exchange pieces in.</extracomment>
        <translation>Eksportēt DXF piegrieztņu programmām (AAMA)…</translation>
    </message>
    <message>
        <source>Each closed curve as a pattern piece (ASTM D6673): its seam allowance as the cut line, the curve as the sew line, polylines within 0.05 mm</source>
        <translation>Katra noslēgta līkne kā piegrieztnes detaļa (ASTM D6673): tās šuves pielaide kā griešanas līnija, līkne kā šuves līnija, lauztas līnijas ar precizitāti 0,05 mm</translation>
    </message>
    <message>
        <source>Export DXF for pattern software</source>
        <translation>Eksportēt DXF piegrieztņu programmām</translation>
    </message>
</context>
<context>
    <name>FileBrowserDialog</name>
    <message>
        <source>Save</source>
        <translation>Saglabāt</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Atvērt</translation>
    </message>
</context>
<context>
    <name>FileBrowserPage</name>
    <message>
        <source>Up one folder</source>
        <extracomment>File dialog: go to the folder that contains this one.</extracomment>
        <translation>Uz augšējo mapi</translation>
    </message>
    <message>
        <source>Folder or file path</source>
        <extracomment>File dialog: the field that shows the folder&apos;s path and takes a typed one.</extracomment>
        <translation>Mapes vai faila ceļš</translation>
    </message>
    <message>
        <source>Go</source>
        <extracomment>File dialog: go to the folder or file typed into the path field.</extracomment>
        <translation>Doties</translation>
    </message>
    <message>
        <source>There is no folder or file “%1”.</source>
        <translation>Nav mapes vai faila „%1“.</translation>
    </message>
    <message>
        <source>The folder “%1” cannot be read.</source>
        <translation>Mapi „%1“ nevar nolasīt.</translation>
    </message>
    <message>
        <source>Type a name for the file.</source>
        <translation>Ierakstiet faila nosaukumu.</translation>
    </message>
    <message>
        <source>No folders and no matching files here.</source>
        <extracomment>File dialog: the folder shown has no subfolder and no file that the filter lets through.</extracomment>
        <translation>Šeit nav ne mapju, ne atbilstošu failu.</translation>
    </message>
    <message>
        <source>Files of type</source>
        <extracomment>File dialog: which kinds of files the list shows.</extracomment>
        <translation>Failu veids</translation>
    </message>
    <message>
        <source>Name</source>
        <extracomment>File dialog: the name of the file to save.</extracomment>
        <translation>Nosaukums</translation>
    </message>
    <message>
        <source>File name</source>
        <translation>Faila nosaukums</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Atcelt</translation>
    </message>
    <message>
        <source>Replace the file?</source>
        <translation>Aizstāt failu?</translation>
    </message>
    <message>
        <source>“%1” already exists. Replace it?</source>
        <translation>„%1“ jau eksistē. Vai aizstāt to?</translation>
    </message>
    <message>
        <source>Replace</source>
        <translation>Aizstāt</translation>
    </message>
</context>
<context>
    <name>FirstRunHint</name>
    <message>
        <source>New curve</source>
        <translation>Jauna līkne</translation>
    </message>
    <message>
        <source>Tap four points of a Bézier curve</source>
        <translation>Pieskarieties četriem Bezjē līknes punktiem</translation>
    </message>
    <message>
        <source>Open a file</source>
        <translation>Atvērt failu</translation>
    </message>
    <message>
        <source>A Kontur document</source>
        <translation>Kontur dokuments</translation>
    </message>
    <message>
        <source>Trace a picture</source>
        <translation>Pārzīmēt attēlu</translation>
    </message>
    <message>
        <source>Load a photo or scan and draw over it</source>
        <translation>Ielādējiet fotoattēlu vai skenējumu un zīmējiet uz tā</translation>
    </message>
</context>
<context>
    <name>FunctionSplinePlot</name>
    <message>
        <source>Change the function spline</source>
        <translation>Mainīt funkcijas splainu</translation>
    </message>
</context>
<context>
    <name>FunctionSplineView</name>
    <message>
        <source>Function spline y(x)</source>
        <translation>Funkcijas splains y(x)</translation>
    </message>
    <message>
        <source>Close</source>
        <extracomment>Button (verb): closes this teaching view and returns to the drawing.</extracomment>
        <translation>Aizvērt</translation>
    </message>
    <message>
        <source>Spline</source>
        <extracomment>Heading (noun): the kind of spline to draw.</extracomment>
        <translation>Splains</translation>
    </message>
    <message>
        <source>Natural spline</source>
        <translation>Dabiskais splains</translation>
    </message>
    <message>
        <source>Clamped spline (C-spline)</source>
        <translation>Nostiprinātais splains (C-splains)</translation>
    </message>
    <message>
        <source>Hermite spline (H-spline)</source>
        <translation>Ermita splains (H-splains)</translation>
    </message>
    <message>
        <source>Global B-spline</source>
        <translation>Globālais B-splains</translation>
    </message>
    <message>
        <source>B-spline of bell functions</source>
        <translation>Zvanveida funkciju B-splains</translation>
    </message>
    <message>
        <source>Control values</source>
        <translation>Kontrolvērtības</translation>
    </message>
    <message>
        <source>Function values</source>
        <translation>Funkcijas vērtības</translation>
    </message>
    <message>
        <source>Regular (uniform) knots</source>
        <translation>Regulāri (vienmērīgi izvietoti) mezgli</translation>
    </message>
    <message>
        <source>Interval</source>
        <extracomment>Heading (noun): the interval [a, b] of evenly spaced knots; otherwise the knots x₀ … xₙ are typed one by one.</extracomment>
        <translation>Intervāls</translation>
    </message>
    <message>
        <source>Knots</source>
        <translation>Mezgli</translation>
    </message>
    <message>
        <source>Derivatives (one per knot)</source>
        <translation>Atvasinājumi (viens katram mezglam)</translation>
    </message>
    <message>
        <source>Derivatives (first and last knot)</source>
        <translation>Atvasinājumi (pirmajā un pēdējā mezglā)</translation>
    </message>
    <message>
        <source>Derivatives</source>
        <extracomment>Screen-reader name of the field for the derivatives at the two ends (clamped spline).</extracomment>
        <translation>Atvasinājumi</translation>
    </message>
    <message>
        <source>Draw</source>
        <extracomment>Button (verb): draws the spline from the values typed above.</extracomment>
        <translation>Zīmēt</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Atsaukt</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Atkārtot</translation>
    </message>
    <message>
        <source>Interpolating polynomial through the same points</source>
        <translation>Interpolācijas polinoms caur tiem pašiem punktiem</translation>
    </message>
    <message>
        <source>Runge&apos;s example</source>
        <translation>Runges piemērs</translation>
    </message>
    <message>
        <source>Points of Runge&apos;s example</source>
        <translation>Runges piemēra punkti</translation>
    </message>
    <message>
        <source>Drag a green knot up or down, or a grey handle to change the derivative: its slope to the knot is the derivative.</source>
        <translation>Velciet zaļu mezgla punktu augšup vai lejup vai pelēku rokturi, lai mainītu atvasinājumu: atvasinājums ir slīpums no mezgla punkta līdz rokturim.</translation>
    </message>
    <message>
        <source>Runge phenomenon: comparison</source>
        <translation>Runges fenomens: salīdzinājums</translation>
    </message>
    <message>
        <source>Solver</source>
        <translation>Risināšanas metode</translation>
    </message>
    <message>
        <source>Classical: k − 2 unknowns</source>
        <translation>Klasiskā: k − 2 nezināmie</translation>
    </message>
    <message>
        <source>Török: half-size system</source>
        <translatorcomment>Török kept in its Hungarian spelling, with the Latvian genitive ending, as mathematical texts cite the method.</translatorcomment>
        <translation>Töröka: uz pusi mazāka sistēma</translation>
    </message>
    <message>
        <source>Add to document</source>
        <translation>Pievienot dokumentam</translation>
    </message>
    <message>
        <source>Added to the document as “%1”.</source>
        <translation>Pievienots dokumentam kā „%1“.</translation>
    </message>
    <message>
        <source>Add this spline to the drawing as a curve (undone in one step)</source>
        <translation>Pievienot šo splainu zīmējumam kā līkni (to var atsaukt vienā solī)</translation>
    </message>
    <message>
        <source>Course examples</source>
        <extracomment>Heading: buttons that load the course&apos;s worked examples.</extracomment>
        <translation>Kursa piemēri</translation>
    </message>
    <message>
        <source>Török&apos;s example</source>
        <extracomment>Button: loads Török&apos;s example (values 3 2 −1 0,5, end slopes 0, his solver).</extracomment>
        <translation>Töröka piemērs</translation>
    </message>
    <message>
        <source>Example 1.23</source>
        <extracomment>Button: loads the course&apos;s Example 1.23 (a global B-spline); keep the number.</extracomment>
        <translation>1.23. piemērs</translation>
    </message>
    <message>
        <source>Example 1.30</source>
        <extracomment>Button: loads the course&apos;s Example 1.30 (a Hermite spline); keep the number.</extracomment>
        <translation>1.30. piemērs</translation>
    </message>
</context>
<context>
    <name>Main</name>
    <message>
        <source>Kontur</source>
        <translation>Kontur</translation>
    </message>
    <message>
        <source>Press “New Bézier” and tap 4 points to draw your first curve.</source>
        <translation>Nospiediet „Jauna Bezjē līkne“ un pieskarieties 4 punktiem, lai uzzīmētu pirmo līkni.</translation>
    </message>
    <message>
        <source>Drag a point to move it. Drag the canvas to pan; pinch or scroll to zoom.</source>
        <translation>Velciet punktu, lai to pārvietotu. Velciet audeklu, lai pārvietotu skatu; savelciet ar diviem pirkstiem vai ritiniet, lai pietuvinātu vai attālinātu.</translation>
    </message>
    <message>
        <source>New curve: tap or click its points (%1 placed). Press Done to finish, Esc to cancel.</source>
        <translation>Jauna līkne: pieskarieties tās punktiem vai noklikšķiniet uz tiem (novietoti %1). Nospiediet „Gatavs“, lai pabeigtu, Esc — lai atceltu.</translation>
    </message>
    <message>
        <source>New curve: tap or click point %1 of %2. Esc cancels.</source>
        <translation>Jauna līkne: pieskarieties vai noklikšķiniet, lai novietotu %1. punktu no %2. Esc atceļ.</translation>
    </message>
    <message>
        <source>Grainline: tap its other end.</source>
        <translation>Diega virziens: pieskarieties tā otram galam.</translation>
    </message>
    <message>
        <source>Grainline: tap one end, then the other.</source>
        <translation>Diega virziens: pieskarieties vienam galam, tad otram.</translation>
    </message>
    <message>
        <source>On fold: tap the fold line&apos;s other end.</source>
        <translation>Uz locījuma: pieskarieties locījuma līnijas otram galam.</translation>
    </message>
    <message>
        <source>On fold: tap one end of the fold line, then the other.</source>
        <translation>Uz locījuma: pieskarieties vienam locījuma līnijas galam, tad otram.</translation>
    </message>
    <message>
        <source>Notch: tap the seam to place one; drag a notch to slide it along the seam.</source>
        <translation>Iegriezums: pieskarieties šuvei, lai to novietotu; velciet iegriezumu, lai to pārvietotu gar šuvi.</translation>
    </message>
    <message>
        <source>Drill hole: tap where it goes.</source>
        <translation>Urbuma atzīme: pieskarieties vietai, kur tā būs.</translation>
    </message>
    <message>
        <source>Delete mark: tap a notch, drill hole, grainline or fold line.</source>
        <translation>Dzēst atzīmi: pieskarieties iegriezumam, urbuma atzīmei, diega virzienam vai locījuma līnijai.</translation>
    </message>
    <message>
        <source>Seam allowance: tap a seam, then set its width in the bar.</source>
        <translation>Šuves pielaide: pieskarieties šuvei, tad iestatiet tās platumu joslā.</translation>
    </message>
</context>
<context>
    <name>MessageBanner</name>
    <message>
        <source>Close message</source>
        <translation>Aizvērt ziņojumu</translation>
    </message>
    <message>
        <source>Change units…</source>
        <extracomment>Button in the message that a DXF without units was read in the units chosen for such files.</extracomment>
        <translation>Mainīt mērvienības…</translation>
    </message>
</context>
<context>
    <name>NumberStepper</name>
    <message>
        <source>%1 of %2</source>
        <extracomment>Which number of a typed list the − and + buttons change: %1 its place, %2 how many there are.</extracomment>
        <translation>%1 no %2</translation>
    </message>
    <message>
        <source>Previous number</source>
        <extracomment>Screen-reader name: chooses the previous number of the list for the − and + buttons.</extracomment>
        <translation>Iepriekšējais skaitlis</translation>
    </message>
    <message>
        <source>Next number</source>
        <extracomment>Screen-reader name: chooses the next number of the list for the − and + buttons.</extracomment>
        <translation>Nākamais skaitlis</translation>
    </message>
    <message>
        <source>Decrease the marked number</source>
        <extracomment>Screen-reader name: makes the marked number of the list smaller by the step shown.</extracomment>
        <translation>Samazināt iezīmēto skaitli</translation>
    </message>
    <message>
        <source>Increase the marked number</source>
        <extracomment>Screen-reader name: makes the marked number of the list larger by the step shown.</extracomment>
        <translation>Palielināt iezīmēto skaitli</translation>
    </message>
</context>
<context>
    <name>PanelDrawer</name>
    <message>
        <source>Curves and settings</source>
        <translation>Līknes un iestatījumi</translation>
    </message>
    <message>
        <source>Unpin</source>
        <extracomment>Button (verb): let the side panel slide over the canvas instead of staying beside it.</extracomment>
        <translation>Atspraust</translation>
    </message>
    <message>
        <source>Pin</source>
        <extracomment>Button (verb): keep the side panel open beside the canvas.</extracomment>
        <translation>Piespraust</translation>
    </message>
    <message>
        <source>Unpin the panel: let it slide over the canvas</source>
        <translation>Atspraust paneli, lai tas slīdētu pāri audeklam</translation>
    </message>
    <message>
        <source>Pin the panel beside the canvas</source>
        <translation>Piespraust paneli blakus audeklam</translation>
    </message>
</context>
<context>
    <name>PieceBar</name>
    <message>
        <source>Pattern piece</source>
        <extracomment>Title of the bar that edits a garment pattern piece&apos;s marks.</extracomment>
        <translation>Piegrieztnes detaļa</translation>
    </message>
    <message>
        <source>Make a pattern piece</source>
        <translation>Padarīt par piegrieztnes detaļu</translation>
    </message>
    <message>
        <source>Select a closed curve: the outline of a pattern piece.</source>
        <translation>Atlasiet slēgtu līkni — piegrieztnes detaļas kontūru.</translation>
    </message>
    <message>
        <source>Size</source>
        <extracomment>A garment size (38, M) of the pattern piece.</extracomment>
        <translation>Izmērs</translation>
    </message>
    <message>
        <source>Cut</source>
        <extracomment>How many pieces to cut from the fabric (“cut 2”).</extracomment>
        <translation>Piegriezt</translation>
    </message>
    <message>
        <source>How many to cut</source>
        <translation>Cik piegriezt</translation>
    </message>
    <message>
        <source>Material</source>
        <extracomment>The fabric the pattern piece is cut from.</extracomment>
        <translation>Materiāls</translation>
    </message>
    <message>
        <source>Grainline</source>
        <extracomment>Tool: draw the pattern piece&apos;s grainline with two taps.</extracomment>
        <translation>Diega virziens</translation>
    </message>
    <message>
        <source>On fold</source>
        <extracomment>Tool: the fold line, the edge laid on the fabric&apos;s fold (two taps).</extracomment>
        <translation>Uz locījuma</translation>
    </message>
    <message>
        <source>Notch</source>
        <extracomment>Tool: place a notch by tapping the seam.</extracomment>
        <translation>Iegriezums</translation>
    </message>
    <message>
        <source>Slit notch</source>
        <translation>Taisns iegriezums</translation>
    </message>
    <message>
        <source>V notch</source>
        <translation>V iegriezums</translation>
    </message>
    <message>
        <source>Castle notch</source>
        <translation>Taisnstūra iegriezums</translation>
    </message>
    <message>
        <source>Notch kind</source>
        <translation>Iegriezuma veids</translation>
    </message>
    <message>
        <source>Drill hole</source>
        <extracomment>Tool: mark a drill hole by a tap.</extracomment>
        <translation>Urbuma atzīme</translation>
    </message>
    <message>
        <source>Delete mark</source>
        <extracomment>Tool: delete the notch, drill hole, grainline or fold line tapped.</extracomment>
        <translation>Dzēst atzīmi</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>Gatavs</translation>
    </message>
    <message>
        <source>Close the pattern piece bar</source>
        <translation>Aizvērt piegrieztnes detaļas joslu</translation>
    </message>
    <message>
        <source>Seam allowance</source>
        <extracomment>Tool: tap a seam of the pattern piece to set its own seam allowance width.</extracomment>
        <translation>Šuves pielaide</translation>
    </message>
    <message>
        <source>Seam %1</source>
        <extracomment>The seam tapped (numbered from 1 along the piece) whose seam allowance the bar shows.</extracomment>
        <translation>Šuve %1</translation>
    </message>
    <message>
        <source>Seam allowance %1 %2 narrower</source>
        <translation>Šuves pielaide par %1 %2 šaurāka</translation>
    </message>
    <message>
        <source>Seam allowance of the seam</source>
        <translation>Šīs šuves pielaide</translation>
    </message>
    <message>
        <source>Seam allowance %1 %2 wider</source>
        <translation>Šuves pielaide par %1 %2 platāka</translation>
    </message>
    <message>
        <source>As the piece</source>
        <extracomment>Give the seam the piece&apos;s own seam allowance width again.</extracomment>
        <translation>Kā detaļai</translation>
    </message>
    <message>
        <source>Hem: turned-back corners</source>
        <extracomment>Toggle: the tapped seam is a hem, so its seam allowance&apos;s corners are turned back (mirrored about the hem line) rather than mitred.</extracomment>
        <translation>Apakšmala: atlocīti stūri</translation>
    </message>
</context>
<context>
    <name>PracticumPlot</name>
    <message>
        <source>Change the segments</source>
        <translation>Mainīt segmentus</translation>
    </message>
</context>
<context>
    <name>PracticumView</name>
    <message>
        <source>Cubic segments</source>
        <translation>Kubiskie segmenti</translation>
    </message>
    <message>
        <source>Close</source>
        <extracomment>Button (verb): closes this teaching view and returns to the drawing.</extracomment>
        <translation>Aizvērt</translation>
    </message>
    <message>
        <source>Parametric segment</source>
        <translation>Parametrisks segments</translation>
    </message>
    <message>
        <source>Spline through several points</source>
        <translation>Splains caur vairākiem punktiem</translation>
    </message>
    <message>
        <source>Kind of segment</source>
        <translation>Segmenta veids</translation>
    </message>
    <message>
        <source>Lines per segment</source>
        <translation>Nogriežņu skaits segmentā</translation>
    </message>
    <message>
        <source>By lines</source>
        <translation>Ar nogriežņiem</translation>
    </message>
    <message>
        <source>By points</source>
        <translation>Ar punktiem</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Atsaukt</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Atkārtot</translation>
    </message>
    <message>
        <source>Drag the green points, or the grey grips at the ends of the guide vectors to change the end directions.</source>
        <translation>Velciet zaļos punktus vai pelēkos rokturus virziena vektoru galos, lai mainītu galu virzienus.</translation>
    </message>
    <message>
        <source>Function segment y(x)</source>
        <translation>Funkcijas segments y(x)</translation>
    </message>
    <message>
        <source>Test example</source>
        <translation>Testa piemērs</translation>
    </message>
    <message>
        <source>Segment example</source>
        <extracomment>Button: loads the practicum&apos;s single-segment example (KG-202: two points, guide vectors rising and falling at 45°), in the segment kind chosen.</extracomment>
        <translation>Segmenta piemērs</translation>
    </message>
</context>
<context>
    <name>PrintDialog</name>
    <message>
        <source>Print pattern</source>
        <translation>Drukāt piegrieztni</translation>
    </message>
    <message>
        <source>Print to PDF…</source>
        <translation>Drukāt PDF failā…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Atcelt</translation>
    </message>
    <message>
        <source>Paper</source>
        <translation>Papīrs</translation>
    </message>
    <message>
        <source>Letter</source>
        <extracomment>The US paper size Letter (8.5 × 11 in), not a letter of the alphabet or a message.</extracomment>
        <translation>Letter (ASV)</translation>
    </message>
    <message>
        <source>Orientation</source>
        <translation>Orientācija</translation>
    </message>
    <message>
        <source>Automatic (fewer pages)</source>
        <translation>Automātiski (mazāk lapu)</translation>
    </message>
    <message>
        <source>Portrait</source>
        <translation>Portrets</translation>
    </message>
    <message>
        <source>Landscape</source>
        <translation>Ainava</translation>
    </message>
    <message>
        <source>Overlap (mm)</source>
        <translation>Pārklāšanās (mm)</translation>
    </message>
    <message numerus="yes">
        <source>%n page(s) to tape together: %1 × %2 (rows × columns), %3.</source>
        <translation>
            <numerusform>Jāsalīmē %n lapa: %1 × %2 (rindas × kolonnas), %3.</numerusform>
            <numerusform>Jāsalīmē %n lapas: %1 × %2 (rindas × kolonnas), %3.</numerusform>
            <numerusform>Jāsalīmē %n lapu: %1 × %2 (rindas × kolonnas), %3.</numerusform>
        </translation>
    </message>
    <message>
        <source>landscape</source>
        <translation>ainavas orientācija</translation>
    </message>
    <message>
        <source>portrait</source>
        <translation>portreta orientācija</translation>
    </message>
    <message>
        <source>Before them, a first page with a 10 cm test square and the overview. Print at 100 % (actual size). The visible curves are printed; the background picture is not.</source>
        <translation>Pirms tām — pirmā lapa ar 10 cm kontrolkvadrātu un pārskatu. Drukājiet 100 % mērogā (faktiskajā izmērā). Tiek drukātas redzamās līknes, fona attēls netiek drukāts.</translation>
    </message>
    <message>
        <source>The drawing is in px: it is printed at 96 px per inch. Choose real units for true size.</source>
        <translation>Zīmējums ir pikseļos (px): to drukā ar 96 px collā. Lai iegūtu īsto izmēru, izvēlieties reālas mērvienības.</translation>
    </message>
</context>
<context>
    <name>SeamAllowanceDialog</name>
    <message>
        <source>Seam allowance</source>
        <translation>Šuves pielaide</translation>
    </message>
    <message>
        <source>Width (%1)</source>
        <extracomment>Label: the seam allowance&apos;s width; %1 is the unit (mm, cm…).</extracomment>
        <translation>Platums (%1)</translation>
    </message>
    <message>
        <source>Seam allowance width</source>
        <translation>Šuves pielaides platums</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Puse</translation>
    </message>
    <message>
        <source>Outside</source>
        <translation>Ārpusē</translation>
    </message>
    <message>
        <source>Inside</source>
        <translation>Iekšpusē</translation>
    </message>
    <message>
        <source>Left of the direction</source>
        <translation>Pa kreisi no virziena</translation>
    </message>
    <message>
        <source>Right of the direction</source>
        <translation>Pa labi no virziena</translation>
    </message>
    <message>
        <source>Corners</source>
        <translation>Stūri</translation>
    </message>
    <message>
        <source>Mitered</source>
        <translation>Smaili</translation>
    </message>
    <message>
        <source>Bevelled</source>
        <translation>Nošķelti</translation>
    </message>
    <message>
        <source>Rounded</source>
        <translation>Noapaļoti</translation>
    </message>
    <message>
        <source>Miter limit (%1)</source>
        <extracomment>Label: the longest pointed corner; %1 is the unit (mm, cm…).</extracomment>
        <translation>Smailā stūra robeža (%1)</translation>
    </message>
    <message>
        <source>Miter limit</source>
        <translation>Smailā stūra robeža</translation>
    </message>
    <message>
        <source>Apply</source>
        <extracomment>Button (verb): applies the changed settings to this seam allowance.</extracomment>
        <translation>Lietot</translation>
    </message>
    <message>
        <source>Add</source>
        <extracomment>Button (verb): adds a seam allowance to the selected curve.</extracomment>
        <translation>Pievienot</translation>
    </message>
    <message>
        <source>Detach</source>
        <extracomment>Button (verb): cut the link between the seam allowance and its curve, so it can be edited on its own.</extracomment>
        <translation>Atsaistīt</translation>
    </message>
    <message>
        <source>Detach from its curve</source>
        <translation>Atsaistīt no tās līknes</translation>
    </message>
    <message>
        <source>Close</source>
        <extracomment>Button (verb): closes this dialog.</extracomment>
        <translation>Aizvērt</translation>
    </message>
    <message>
        <source>Computing the seam allowance…</source>
        <translation>Aprēķina šuves pielaidi…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Atcelt</translation>
    </message>
    <message>
        <source>Cancel the seam allowance</source>
        <translation>Atcelt šuves pielaides aprēķinu</translation>
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
        <extracomment>%1 is the curve&apos;s kind, %2 its length with its unit (12.5 mm).</extracomment>
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
        <extracomment>Label (noun): the kind of the selected curve, for example “Bézier curve” or “Natural spline”.</extracomment>
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
        <extracomment>Label (noun): the order k of a B-spline (degree + 1), a number; not a sequence and not a command.</extracomment>
        <translation>Kārta</translation>
    </message>
    <message>
        <source>Node type</source>
        <translation>Mezgla veids</translation>
    </message>
    <message>
        <source>Smooth</source>
        <extracomment>Knot type: the handles on both sides stay on one line (G1).</extracomment>
        <translation>Gluds</translation>
    </message>
    <message>
        <source>Symmetric</source>
        <extracomment>Knot type: the handles on both sides stay on one line and have equal lengths (C1).</extracomment>
        <translation>Simetrisks</translation>
    </message>
    <message>
        <source>Corner</source>
        <extracomment>Knot type: the handles on both sides move independently (a corner).</extracomment>
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
        <extracomment>Heading (noun): figures about the selected curve (length, fit error, continuity).</extracomment>
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
    <message>
        <source>%1 / %2</source>
        <extracomment>The fit error as RMS / maximum: %1 and %2 are numbers.</extracomment>
        <translation>%1 / %2</translation>
    </message>
    <message>
        <source>No curve selected. Tap a curve to edit it.</source>
        <translation>Nav atlasīta neviena līkne. Pieskarieties līknei, lai to mainītu.</translation>
    </message>
    <message>
        <source>Curve visible</source>
        <translation>Līkne redzama</translation>
    </message>
    <message>
        <source>Curve locked</source>
        <translation>Līkne bloķēta</translation>
    </message>
    <message>
        <source>Curve name</source>
        <translation>Līknes nosaukums</translation>
    </message>
    <message>
        <source>Black</source>
        <translation>Melna</translation>
    </message>
    <message>
        <source>Red</source>
        <translation>Sarkana</translation>
    </message>
    <message>
        <source>Blue</source>
        <translation>Zila</translation>
    </message>
    <message>
        <source>Green</source>
        <translation>Zaļa</translation>
    </message>
    <message>
        <source>Orange</source>
        <translation>Oranža</translation>
    </message>
    <message>
        <source>Purple</source>
        <translation>Violeta</translation>
    </message>
    <message>
        <source>Teal</source>
        <translation>Zilganzaļa</translation>
    </message>
    <message>
        <source>Brown</source>
        <translation>Brūna</translation>
    </message>
    <message>
        <source>Colour: %1</source>
        <translation>Krāsa: %1</translation>
    </message>
    <message>
        <source>Load background image</source>
        <translation>Ielādēt fona attēlu</translation>
    </message>
    <message>
        <source>Background opacity</source>
        <translation>Fona necaurredzamība</translation>
    </message>
    <message>
        <source>Pattern piece…</source>
        <extracomment>Opens the bar that makes the closed curve a garment pattern piece and edits its marks.</extracomment>
        <translation>Piegrieztnes detaļa…</translation>
    </message>
    <message>
        <source>Pattern piece</source>
        <translation>Piegrieztnes detaļa</translation>
    </message>
</context>
<context>
    <name>SimplifyDialog</name>
    <message>
        <source>Simplify curve</source>
        <translation>Vienkāršot līkni</translation>
    </message>
    <message>
        <source>The new curve stays within this distance of the old one.</source>
        <translation>Jaunā līkne no vecās neatkāpjas tālāk par šo attālumu.</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Precizitāte</translation>
    </message>
    <message>
        <source>Simplify</source>
        <translation>Vienkāršot</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Atcelt</translation>
    </message>
</context>
<context>
    <name>TeachingBar</name>
    <message>
        <source>de Casteljau</source>
        <translation>de Casteljau</translation>
    </message>
    <message>
        <source>Degree elevation</source>
        <translation>Pakāpes paaugstināšana</translation>
    </message>
    <message>
        <source>Compare</source>
        <extracomment>Name of a teaching view (verb used as a title): compare curve kinds or parameterizations side by side.</extracomment>
        <translation>Salīdzināt</translation>
    </message>
    <message>
        <source>Curvature comb</source>
        <translation>Liekuma ķemme</translation>
    </message>
    <message>
        <source>Select a Bézier curve.</source>
        <translation>Atlasiet Bezjē līkni.</translation>
    </message>
    <message>
        <source>Select a curve.</source>
        <translation>Atlasiet līkni.</translation>
    </message>
    <message>
        <source>t = %1</source>
        <extracomment>The curve parameter t and its value (a number); keep “t”.</extracomment>
        <translation>t = %1</translation>
    </message>
    <message>
        <source>Parameter t</source>
        <translation>Parametrs t</translation>
    </message>
    <message numerus="yes">
        <source>degree %1 → %2 (%n point(s))</source>
        <translation>
            <numerusform>pakāpe %1 → %2 (%n punkts)</numerusform>
            <numerusform>pakāpe %1 → %2 (%n punkti)</numerusform>
            <numerusform>pakāpe %1 → %2 (%n punktu)</numerusform>
        </translation>
    </message>
    <message>
        <source>Elevation steps</source>
        <translation>Paaugstināšanas soļi</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pauzēt</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Atskaņot</translation>
    </message>
    <message>
        <source>Play or pause the animation (P)</source>
        <translation>Atskaņot vai pauzēt animāciju (P)</translation>
    </message>
    <message>
        <source>Direction</source>
        <extracomment>Screen-reader name of the button that reverses the direction of the animation (forwards or backwards in t).</extracomment>
        <translation>Virziens</translation>
    </message>
    <message>
        <source>Forward; press to go backward</source>
        <translation>Uz priekšu; nospiediet, lai virzītos atpakaļ</translation>
    </message>
    <message>
        <source>Backward; press to go forward</source>
        <translation>Atpakaļ; nospiediet, lai virzītos uz priekšu</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Ātrums</translation>
    </message>
    <message>
        <source>%1×</source>
        <extracomment>Animation speed factor: %1 is a number (0,5 → “0,5×”).</extracomment>
        <translation>%1×</translation>
    </message>
    <message>
        <source>Split at t</source>
        <translation>Sadalīt punktā t</translation>
    </message>
    <message>
        <source>Reduce degree</source>
        <translation>Pazemināt pakāpi</translation>
    </message>
    <message>
        <source>Replace the curve by the closest curve of one degree less</source>
        <translation>Aizstāt līkni ar tuvāko līkni, kuras pakāpe ir par vienu mazāka</translation>
    </message>
    <message>
        <source>reduction error %1</source>
        <extracomment>Degree reduction: %1 is the largest distance between the curve and its reduced curve (a number).</extracomment>
        <translation>pazemināšanas kļūda %1</translation>
    </message>
    <message>
        <source>Alt+click or long press: add or remove a control point</source>
        <translation>Alt+klikšķis vai ilga nospiešana: pievienot vai noņemt kontrolpunktu</translation>
    </message>
    <message>
        <source>Curve kinds</source>
        <extracomment>What the Compare view sets side by side: one curve drawn as each kind, or with each parameterization.</extracomment>
        <translation>Līkņu veidi</translation>
    </message>
    <message>
        <source>Parameterizations</source>
        <translation>Parametrizācijas</translation>
    </message>
    <message>
        <source>Scale %1</source>
        <extracomment>%1 is the scale factor of the curvature comb (a number such as 2,5).</extracomment>
        <translation>Mērogs %1</translation>
    </message>
    <message>
        <source>Comb scale</source>
        <translation>Ķemmes mērogs</translation>
    </message>
    <message>
        <source>All curves</source>
        <translation>Visas līknes</translation>
    </message>
    <message>
        <source>Close</source>
        <extracomment>Button (verb): closes the teaching view and returns to the drawing.</extracomment>
        <translation>Aizvērt</translation>
    </message>
    <message>
        <source>Leave the teaching view</source>
        <translation>Iziet no mācību skata</translation>
    </message>
    <message>
        <source>Split the curve at t into two curves (a spline becomes a composite curve first)</source>
        <translation>Sadalīt līkni punktā t divās līknēs (splains vispirms kļūst par saliktu līkni)</translation>
    </message>
    <message>
        <source>One elevation step less</source>
        <translation>Par vienu paaugstināšanas soli mazāk</translation>
    </message>
    <message>
        <source>One elevation step more</source>
        <translation>Par vienu paaugstināšanas soli vairāk</translation>
    </message>
    <message>
        <source>One step back in t</source>
        <translation>Par vienu soli atpakaļ pa t</translation>
    </message>
    <message>
        <source>One step forward in t</source>
        <translation>Par vienu soli uz priekšu pa t</translation>
    </message>
</context>
<context>
    <name>TeachingOverlay</name>
    <message>
        <source>%1 (not possible for these points)</source>
        <translation>%1 (šiem punktiem nav iespējams)</translation>
    </message>
</context>
<context>
    <name>TraceBar</name>
    <message>
        <source>Freehand</source>
        <translation>Ar brīvu roku</translation>
    </message>
    <message>
        <source>Calibrate</source>
        <translation>Kalibrēt</translation>
    </message>
    <message>
        <source>Measure</source>
        <translation>Mērīt</translation>
    </message>
    <message>
        <source>Seam length</source>
        <translation>Šuves garums</translation>
    </message>
    <message>
        <source>Deviation</source>
        <translation>Novirze</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Precizitāte</translation>
    </message>
    <message numerus="yes">
        <source>last stroke: %n segment(s)</source>
        <translation>
            <numerusform>pēdējais vilkums: %n segments</numerusform>
            <numerusform>pēdējais vilkums: %n segmenti</numerusform>
            <numerusform>pēdējais vilkums: %n segmentu</numerusform>
        </translation>
    </message>
    <message>
        <source>Real distance</source>
        <translation>Reālais attālums</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Mērvienība</translation>
    </message>
    <message>
        <source>Keep the angle</source>
        <translation>Saglabāt leņķi</translation>
    </message>
    <message>
        <source>Make it horizontal</source>
        <translation>Padarīt horizontālu</translation>
    </message>
    <message>
        <source>Make it vertical</source>
        <translation>Padarīt vertikālu</translation>
    </message>
    <message>
        <source>Alignment</source>
        <translation>Izlīdzināšana</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Lietot</translation>
    </message>
    <message>
        <source>Distance %1</source>
        <extracomment>%1 is a length with its unit, for example “12,35 mm”.</extracomment>
        <translation>Attālums %1</translation>
    </message>
    <message>
        <source>Seam %1</source>
        <extracomment>%1 is the seam length with its unit, for example “412,50 mm”.</extracomment>
        <translation>Šuve %1</translation>
    </message>
    <message>
        <source>Maximum %1 · mean %2</source>
        <extracomment>Deviation of a traced curve from the reference curve: %1 and %2 are lengths with their unit.</extracomment>
        <translation>Maksimums %1 · vidēji %2</translation>
    </message>
    <message>
        <source>Snap</source>
        <extracomment>Check box (verb): snap freehand strokes to the edges seen in the picture.</extracomment>
        <translation>Piesaiste</translation>
    </message>
    <message>
        <source>Leave the tracing tool</source>
        <translation>Iziet no pārzīmēšanas rīka</translation>
    </message>
    <message>
        <source>Move background</source>
        <translation>Pārvietot fonu</translation>
    </message>
    <message>
        <source>Perspective</source>
        <translation>Perspektīva</translation>
    </message>
    <message>
        <source>A4 sheet (210 × 297 mm)</source>
        <translation>A4 lapa (210 × 297 mm)</translation>
    </message>
    <message>
        <source>A3 sheet (297 × 420 mm)</source>
        <translation>A3 lapa (297 × 420 mm)</translation>
    </message>
    <message>
        <source>Letter sheet (8.5 × 11 in)</source>
        <translation>Letter lapa (8,5 × 11″)</translation>
    </message>
    <message>
        <source>Mat square 1 cm</source>
        <translation>Paklāja rūtiņa 1 cm</translation>
    </message>
    <message>
        <source>Mat square 10 cm</source>
        <translation>Paklāja rūtiņa 10 cm</translation>
    </message>
    <message>
        <source>Mat square 1 in</source>
        <translation>Paklāja rūtiņa 1 colla</translation>
    </message>
    <message>
        <source>Mat square 6 in</source>
        <translation>Paklāja rūtiņa 6 collas</translation>
    </message>
    <message>
        <source>Other size</source>
        <translation>Cits izmērs</translation>
    </message>
    <message>
        <source>Known rectangle</source>
        <translation>Zināmais taisnstūris</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Platums</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Augstums</translation>
    </message>
    <message>
        <source>As marked: landscape</source>
        <translation>Kā atzīmēts: ainava</translation>
    </message>
    <message>
        <source>As marked: portrait</source>
        <translation>Kā atzīmēts: portrets</translation>
    </message>
    <message>
        <source>As marked</source>
        <translation>Kā atzīmēts</translation>
    </message>
    <message>
        <source>Portrait</source>
        <translation>Portrets</translation>
    </message>
    <message>
        <source>Landscape</source>
        <translation>Ainava</translation>
    </message>
    <message>
        <source>Orientation</source>
        <translation>Orientācija</translation>
    </message>
    <message>
        <source>Clear perspective</source>
        <translation>Noņemt perspektīvu</translation>
    </message>
    <message>
        <source>Trace outline</source>
        <translation>Pārzīmēt kontūru</translation>
    </message>
    <message>
        <source>Snap to edges</source>
        <translation>Piesaistīt malām</translation>
    </message>
    <message>
        <source>Snap the stroke to the picture&apos;s edges</source>
        <translation>Piesaistīt vilkumu attēla malām</translation>
    </message>
    <message>
        <source>Find the sheet</source>
        <translation>Atrast lapu</translation>
    </message>
    <message>
        <source>Find the sheet in the background image</source>
        <translation>Atrast lapu fona attēlā</translation>
    </message>
    <message>
        <source>Estimated error at the far side: %1 mm</source>
        <translation>Aptuvenā kļūda tālākajā malā: %1 mm</translation>
    </message>
    <message>
        <source>Knots in the last outline: %1</source>
        <translation>Mezgla punkti pēdējā kontūrā: %1</translation>
    </message>
    <message>
        <source>in effect at this zoom: %1</source>
        <extracomment>%1 is the freehand tolerance that applies at the current zoom, with its unit (0,50 mm).</extracomment>
        <translation>spēkā šajā mērogā: %1</translation>
    </message>
</context>
<context>
    <name>TraceOverlay</name>
    <message>
        <source>seam %1</source>
        <extracomment>Label on the canvas: %1 is the seam length with its unit, for example “412,50 mm”.</extracomment>
        <translation>šuve %1</translation>
    </message>
    <message>
        <source>max %1</source>
        <extracomment>Label on the canvas: the largest deviation from the reference curve, %1 a length with its unit.</extracomment>
        <translation>maks. %1</translation>
    </message>
    <message>
        <source>%1 px on the picture</source>
        <extracomment>%1 is a distance in pixels of the background picture (a number).</extracomment>
        <translation>%1 px attēlā</translation>
    </message>
</context>
<context>
    <name>UnitsDialog</name>
    <message>
        <source>Units of the drawing</source>
        <translation>Zīmējuma mērvienības</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>Labi</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Atcelt</translation>
    </message>
    <message>
        <source>“%1” does not say which units its numbers are in. Read them as (asked once for such files):</source>
        <translation>Failā „%1“ nav norādīts, kādās mērvienībās ir tā skaitļi. Lasīt tos kā (jautā vienreiz par šādiem failiem):</translation>
    </message>
    <message>
        <source>Read DXF files that do not say which units their numbers are in as:</source>
        <translation>DXF failus, kuros nav norādīts, kādās mērvienībās ir to skaitļi, lasīt kā:</translation>
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
        <source>kontur: give at most one file to open.</source>
        <translation>kontur: norādiet ne vairāk kā vienu atveramo failu.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: no such file.</source>
        <translation>kontur: nevar atvērt „%1“: šāda faila nav.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: its symbolic links form a loop.</source>
        <translation>kontur: nevar atvērt „%1“: tā simboliskās saites veido cilpu.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: permission denied.</source>
        <translation>kontur: nevar atvērt „%1“: piekļuve liegta.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: it is a folder, not a file.</source>
        <translation>kontur: nevar atvērt „%1“: tā ir mape, nevis fails.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: it is not a regular file (a named pipe or a device).</source>
        <translation>kontur: nevar atvērt „%1“: tas nav parasts fails (tas ir nosaukts kanāls vai ierīce).</translation>
    </message>
</context>
<context>
    <name>errors</name>
    <message>
        <source>the file does not exist or cannot be read.</source>
        <translation>fails neeksistē vai to nevar nolasīt.</translation>
    </message>
    <message>
        <source>the file cannot be written there (a folder that is missing or read-only, or a full disk).</source>
        <translation>failu tur nevar ierakstīt (mape neeksistē vai ir tikai lasāma, vai disks ir pilns).</translation>
    </message>
    <message>
        <source>the file is larger than Kontur reads (%1 MB).</source>
        <extracomment>%1 is a size in megabytes, e.g. &quot;1 000&quot;.</extracomment>
        <translation>fails ir lielāks, nekā Kontur spēj nolasīt (%1 MB).</translation>
    </message>
    <message>
        <source>the file holds more points than Kontur reads (%1).</source>
        <extracomment>%1 is a large number of points, e.g. &quot;6 000 000&quot;.</extracomment>
        <translation>failā ir vairāk punktu, nekā Kontur spēj nolasīt (%1).</translation>
    </message>
    <message>
        <source>the file holds more curves than Kontur reads (%1).</source>
        <translation>failā ir vairāk līkņu, nekā Kontur spēj nolasīt (%1).</translation>
    </message>
    <message>
        <source>the file&apos;s structure is nested deeper than %1 levels.</source>
        <extracomment>The file&apos;s elements (JSON or XML) are nested inside each other deeper than %1 levels.</extracomment>
        <translation>faila struktūras ligzdojuma dziļums pārsniedz %1.</translation>
    </message>
    <message>
        <source>the file is not text in UTF-8.</source>
        <extracomment>UTF-8 is the name of a text encoding; keep it as it is.</extracomment>
        <translation>fails nav UTF-8 teksts.</translation>
    </message>
    <message>
        <source>a number was expected here.</source>
        <translation>šeit bija gaidīts skaitlis.</translation>
    </message>
    <message>
        <source>this number is too large for Kontur, or is not a number.</source>
        <translation>šis skaitlis ir pārāk liels, lai Kontur to varētu apstrādāt, vai arī tas nav skaitlis.</translation>
    </message>
    <message>
        <source>more than a point on this line; in files, numbers are written with a decimal point.</source>
        <extracomment>Shown for &quot;1,5 2,5&quot; in a file: files write numbers with a decimal point.</extracomment>
        <translation>rindā ir vairāk nekā viena punkta koordinātas; failos skaitļus raksta ar decimālpunktu.</translation>
    </message>
    <message>
        <source>a word Kontur does not know at the start of this line.</source>
        <translation>rindas sākumā ir vārds, ko Kontur nepazīst.</translation>
    </message>
    <message>
        <source>this line names a setting but gives no value.</source>
        <translation>rindā ir iestatījuma nosaukums, bet nav tā vērtības.</translation>
    </message>
    <message>
        <source>a text in quotation marks is not closed.</source>
        <translation>pēdiņās ievietotais teksts nav noslēgts.</translation>
    </message>
    <message>
        <source>a curve without points.</source>
        <translation>līkne bez punktiem.</translation>
    </message>
    <message>
        <source>the file holds no points.</source>
        <translation>failā nav neviena punkta.</translation>
    </message>
    <message>
        <source>the first row must be the header “x,y”.</source>
        <extracomment>&quot;x,y&quot; is the first line of the file as it must be written; keep it as it is.</extracomment>
        <translation>pirmajai rindai jābūt virsrakstam „x,y“.</translation>
    </message>
    <message>
        <source>each row must hold exactly two values, x and y.</source>
        <translation>katrā rindā jābūt tieši divām vērtībām: x un y.</translation>
    </message>
    <message>
        <source>a kind of curve this version of Kontur does not know.</source>
        <translation>līknes veids, ko šī Kontur versija nepazīst.</translation>
    </message>
    <message>
        <source>a parameterization this version of Kontur does not know.</source>
        <translation>parametrizācija, ko šī Kontur versija nepazīst.</translation>
    </message>
    <message>
        <source>a kind of knot this version of Kontur does not know.</source>
        <translation>mezgla punkta veids, ko šī Kontur versija nepazīst.</translation>
    </message>
    <message>
        <source>the points must be knots or control points.</source>
        <translation>punktiem jābūt mezgla punktiem vai kontrolpunktiem.</translation>
    </message>
    <message>
        <source>too few or too many points for this kind of curve.</source>
        <translation>šā veida līknei ir par maz vai par daudz punktu.</translation>
    </message>
    <message>
        <source>these points do not suit this kind of curve (knots where control points belong, or the reverse).</source>
        <translation>šie punkti neatbilst šā veida līknei (mezgla punkti kontrolpunktu vietā vai otrādi).</translation>
    </message>
    <message>
        <source>a value outside its range.</source>
        <translation>vērtība ārpus pieļaujamā diapazona.</translation>
    </message>
    <message>
        <source>the document is damaged: it is not well-formed JSON.</source>
        <translation>dokuments ir bojāts: tas nav korekts JSON.</translation>
    </message>
    <message>
        <source>this is not a Kontur document.</source>
        <translation>tas nav Kontur dokuments.</translation>
    </message>
    <message>
        <source>the document was written by a newer version of Kontur.</source>
        <translation>dokuments ir saglabāts ar jaunāku Kontur versiju.</translation>
    </message>
    <message>
        <source>a value the document needs is missing.</source>
        <translation>trūkst vērtības, kas dokumentam vajadzīga.</translation>
    </message>
    <message>
        <source>a value of the wrong type (a number, a text or a list where another belongs).</source>
        <translation>nepareiza tipa vērtība (skaitlis, teksts vai saraksts citas vērtības vietā).</translation>
    </message>
    <message>
        <source>the file is damaged: it is not well-formed XML.</source>
        <translation>fails ir bojāts: tas nav korekts XML.</translation>
    </message>
    <message>
        <source>this is not an SVG drawing.</source>
        <translation>tas nav SVG zīmējums.</translation>
    </message>
    <message>
        <source>the outline of a shape (its path data) is malformed.</source>
        <translation>figūras kontūra (tās ceļa dati) ir kļūdaina.</translation>
    </message>
    <message>
        <source>a transformation of a shape is malformed.</source>
        <translation>figūras transformācija ir kļūdaina.</translation>
    </message>
    <message>
        <source>the drawing holds no shapes Kontur can draw.</source>
        <translation>zīmējumā nav figūru, ko Kontur var uzzīmēt.</translation>
    </message>
    <message>
        <source>this PDF was not printed by Kontur, so it holds no drawing Kontur can open. Open the .kontur document it came from.</source>
        <translation>šo PDF nav izdrukājis Kontur, tāpēc tajā nav zīmējuma, ko Kontur var atvērt. Atveriet .kontur dokumentu, no kura tas izveidots.</translation>
    </message>
    <message>
        <source>the DXF file is damaged or cut short.</source>
        <translation>DXF fails ir bojāts vai nepilnīgs.</translation>
    </message>
    <message>
        <source>the DXF file holds something Kontur cannot read (a binary DXF, or a shape off the drawing plane).</source>
        <translation>DXF failā ir kaut kas, ko Kontur nevar nolasīt (binārs DXF vai figūra ārpus zīmējuma plaknes).</translation>
    </message>
    <message>
        <source>this kind of curve cannot be written in this format.</source>
        <translation>šā veida līkni šajā formātā ierakstīt nevar.</translation>
    </message>
    <message>
        <source>too few points for this kind of curve.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>šā veida līknei ir par maz punktu.</translation>
    </message>
    <message>
        <source>its knots need at least 4 different positions.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>tās mezgla punktiem vajadzīgas vismaz 4 dažādas vietas.</translation>
    </message>
    <message>
        <source>its knots lie too close together to define a curve.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>tās mezgla punkti atrodas pārāk tuvu cits citam, lai noteiktu līkni.</translation>
    </message>
    <message>
        <source>a coordinate is too large for Kontur, or is not a number.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>koordināta ir pārāk liela, lai Kontur to varētu apstrādāt, vai arī tā nav skaitlis.</translation>
    </message>
    <message>
        <source>its values do not define a curve of its kind.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>tās vērtības nenosaka šā veida līkni.</translation>
    </message>
    <message>
        <source>a value out of all proportion to the curve&apos;s size.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>vērtība ir nesamērīga ar līknes izmēru.</translation>
    </message>
    <message>
        <source>it would take more work than Kontur allows for one curve.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>tas prasītu vairāk darba, nekā Kontur pieļauj vienai līknei.</translation>
    </message>
    <message>
        <source>the work was cancelled.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>darbs tika atcelts.</translation>
    </message>
    <message>
        <source>line %1, column %2: %3</source>
        <extracomment>Where in a file: %1 the line, %2 the column (character) in it, %3 what is wrong there.</extracomment>
        <translation>%1. rinda, %2. kolonna: %3</translation>
    </message>
    <message>
        <source>line %1: %2</source>
        <extracomment>Where in a file: %1 the line, %2 what is wrong there.</extracomment>
        <translation>%1. rinda: %2</translation>
    </message>
    <message>
        <source>at %1: %2</source>
        <extracomment>Where in a document: %1 is the place as the file writes it (e.g. curves[3].points[7]), %2 what is wrong.</extracomment>
        <translation>vietā %1: %2</translation>
    </message>
    <message>
        <source>curve %1: %2</source>
        <extracomment>%1 is the curve&apos;s number in the file (1, 2, …), %2 what is wrong with it.</extracomment>
        <translation>%1. līkne: %2</translation>
    </message>
    <message>
        <source>the points do not define a curve (two knots at the same place, or too few different knots).</source>
        <translation>punkti nenosaka līkni (divi mezgla punkti vienā vietā vai par maz dažādu mezgla punktu).</translation>
    </message>
    <message>
        <source>all its points are at the same place.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>visi tās punkti atrodas vienā vietā.</translation>
    </message>
    <message>
        <source>two consecutive knots are at the same place.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>divi secīgi mezgla punkti atrodas vienā vietā.</translation>
    </message>
</context>
<context>
    <name>io</name>
    <message>
        <source>Outline %1</source>
        <extracomment>Automatic name of a curve traced along a piece&apos;s outline in the photo: %1 is a running number.</extracomment>
        <translation>Kontūra %1</translation>
    </message>
</context>
<context>
    <name>kontur</name>
    <message>
        <source>Add %1</source>
        <extracomment>Undo text: %1 is the name of the added curve.</extracomment>
        <translation>Pievienot līkni „%1“</translation>
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
        <extracomment>Automatic name of a new curve: %1 is a running number (Bézier 3).</extracomment>
        <translation>Bezjē līkne Nr. %1</translation>
    </message>
    <message>
        <source>Delete %1</source>
        <extracomment>Undo text: %1 is the name of the deleted curve.</extracomment>
        <translation>Dzēst līkni „%1“</translation>
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
        <translation>Kubiskā līkne caur 4 punktiem</translation>
    </message>
    <message>
        <source>Least-squares cubic</source>
        <translation>Mazāko kvadrātu kubiskā līkne</translation>
    </message>
    <message>
        <source>Composite curve</source>
        <translation>Saliktā līkne</translation>
    </message>
    <message>
        <source>Through 4 points %1</source>
        <extracomment>Automatic name of a new cubic through 4 points: %1 is a running number.</extracomment>
        <translation>Līkne caur 4 punktiem Nr. %1</translation>
    </message>
    <message>
        <source>Least squares %1</source>
        <extracomment>Automatic name of a new least-squares cubic: %1 is a running number.</extracomment>
        <translation>Mazāko kvadrātu līkne Nr. %1</translation>
    </message>
    <message>
        <source>Composite %1</source>
        <extracomment>Automatic name of a new composite curve: %1 is a running number.</extracomment>
        <translation>Saliktā līkne Nr. %1</translation>
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
        <translation>Notīrīt visu</translation>
    </message>
    <message>
        <source>Natural spline</source>
        <translation>Dabiskais splains</translation>
    </message>
    <message>
        <source>Clamped spline</source>
        <extracomment>Curve kind: the cubic spline with given first derivatives at both ends (a complete or clamped spline).</extracomment>
        <translation>Nostiprinātais splains</translation>
    </message>
    <message>
        <source>Not-a-knot spline</source>
        <extracomment>Curve kind: the cubic spline whose second and next-to-last knots are not knots (the third derivative is continuous there).</extracomment>
        <translation>Splains ar nosacījumu „nav mezgls“ (not-a-knot)</translation>
    </message>
    <message>
        <source>Periodic spline</source>
        <translation>Periodiskais splains</translation>
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
        <extracomment>Automatic name of a new curve: %1 is its kind (“Natural spline”), %2 a running number.</extracomment>
        <translatorcomment>Nr. before the running number, as in all automatic curve names: a bare number after a kind name such as „Kontūrlīkne ar savienojumiem viduspunktos“ would read as part of the name.</translatorcomment>
        <translation>%1 Nr. %2</translation>
    </message>
    <message>
        <source>Change order</source>
        <translation>Mainīt splaina kārtu</translation>
    </message>
    <message>
        <source>Untitled</source>
        <extracomment>The name of a document that has not been saved yet (also the suggested file name).</extracomment>
        <translation>Bez nosaukuma</translation>
    </message>
    <message>
        <source>Import %1</source>
        <extracomment>Undo text: %1 is the name of the imported file.</extracomment>
        <translation>Importēt failu „%1“</translation>
    </message>
    <message>
        <source>Split curve</source>
        <translation>Sadalīt līkni</translation>
    </message>
    <message>
        <source>uniform</source>
        <extracomment>Parameterization name in lower case, shown after a kind name (“Natural spline, uniform”).</extracomment>
        <translation>vienmērīgā sadalījuma</translation>
    </message>
    <message>
        <source>chord length</source>
        <extracomment>Parameterization name in lower case, shown after a kind name (“Natural spline, chord length”).</extracomment>
        <translation>hordu garuma</translation>
    </message>
    <message>
        <source>centripetal</source>
        <extracomment>Parameterization name in lower case, shown after a kind name (“Natural spline, centripetal”).</extracomment>
        <translation>centrtieces spēka</translation>
    </message>
    <message>
        <source>Reduce degree</source>
        <translation>Pazemināt pakāpi</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <extracomment>Legend in the Compare view: %1 is a curve kind, %2 a parameterization (“Natural spline, uniform”).</extracomment>
        <translation>%1, %2</translation>
    </message>
    <message>
        <source>Contour curve (midpoint joins)</source>
        <extracomment>Curve kind: quadratic Bézier pieces through the midpoints of the polygon&apos;s sides, joined smoothly there.</extracomment>
        <translation>Kontūrlīkne ar savienojumiem viduspunktos</translation>
    </message>
    <message>
        <source>Nothing to print: no curve is visible.</source>
        <translation>Nav ko drukāt: neviena līkne nav redzama.</translation>
    </message>
    <message>
        <source>The drawing would need more than %1 pages at true size. Check the document&apos;s units.</source>
        <translation>Zīmējumam īstajā izmērā vajadzētu vairāk nekā %1 lapu. Pārbaudiet dokumenta mērvienības.</translation>
    </message>
    <message>
        <source>The drawing cannot be printed: %1</source>
        <translation>Zīmējumu nevar izdrukāt: %1</translation>
    </message>
    <message>
        <source>%1 seam allowance</source>
        <extracomment>Name of a new seam allowance: %1 is the name of its curve.</extracomment>
        <translation>%1 — šuves pielaide</translation>
    </message>
    <message>
        <source>Add seam allowance</source>
        <translation>Pievienot šuves pielaidi</translation>
    </message>
    <message>
        <source>Change seam allowance</source>
        <translation>Mainīt šuves pielaidi</translation>
    </message>
    <message>
        <source>Detach seam allowance</source>
        <translation>Atsaistīt šuves pielaidi</translation>
    </message>
    <message>
        <source>no file name was given</source>
        <translation>netika norādīts faila nosaukums</translation>
    </message>
</context>
<context>
    <name>kontur::FunctionSplinePlot</name>
    <message>
        <source>Function values: “%1” is not a number.</source>
        <translation>Funkcijas vērtības: „%1“ nav skaitlis.</translation>
    </message>
    <message>
        <source>Function values: give between 2 and %1 numbers.</source>
        <translation>Funkcijas vērtības: ievadiet no 2 līdz %1 skaitļiem.</translation>
    </message>
    <message>
        <source>Interval: “%1” is not a number.</source>
        <translation>Intervāls: „%1“ nav skaitlis.</translation>
    </message>
    <message>
        <source>Interval: give two numbers, the smaller first.</source>
        <translation>Intervāls: ievadiet divus skaitļus, vispirms mazāko.</translation>
    </message>
    <message>
        <source>Knots: “%1” is not a number.</source>
        <translation>Mezgli: „%1“ nav skaitlis.</translation>
    </message>
    <message numerus="yes">
        <source>Knots: give %n number(s), one per function value.</source>
        <translation>
            <numerusform>Mezgli: ievadiet %n skaitli, vienu katrai funkcijas vērtībai.</numerusform>
            <numerusform>Mezgli: ievadiet %n skaitļus, vienu katrai funkcijas vērtībai.</numerusform>
            <numerusform>Mezgli: ievadiet %n skaitļu, vienu katrai funkcijas vērtībai.</numerusform>
        </translation>
    </message>
    <message>
        <source>Knots: each knot must be greater than the one before.</source>
        <translation>Mezgli: katram mezglam jābūt lielākam par iepriekšējo.</translation>
    </message>
    <message>
        <source>Derivatives: “%1” is not a number.</source>
        <translation>Atvasinājumi: „%1“ nav skaitlis.</translation>
    </message>
    <message numerus="yes">
        <source>Derivatives: give %n number(s), one per knot.</source>
        <translation>
            <numerusform>Atvasinājumi: ievadiet %n skaitli, vienu katram mezglam.</numerusform>
            <numerusform>Atvasinājumi: ievadiet %n skaitļus, vienu katram mezglam.</numerusform>
            <numerusform>Atvasinājumi: ievadiet %n skaitļu, vienu katram mezglam.</numerusform>
        </translation>
    </message>
    <message>
        <source>Derivatives: give two numbers, at the first and the last knot.</source>
        <translation>Atvasinājumi: ievadiet divus skaitļus — pirmajā un pēdējā mezglā.</translation>
    </message>
    <message>
        <source>Values P at the inner knots: %1</source>
        <translation>Vērtības P iekšējos mezglos: %1</translation>
    </message>
    <message>
        <source>Slopes y′ at the knots: %1</source>
        <translation>Slīpumi y′ mezglos: %1</translation>
    </message>
    <message>
        <source>Polynomial of degree %1: it differs from the spline by up to %2.</source>
        <translation>%1. pakāpes polinoms: tas atšķiras no splaina ne vairāk kā par %2.</translation>
    </message>
    <message numerus="yes">
        <source>The polynomial is drawn for at most %n point(s).</source>
        <translation>
            <numerusform>Polinoms tiek zīmēts ne vairāk kā %n punktam.</numerusform>
            <numerusform>Polinoms tiek zīmēts ne vairāk kā %n punktiem.</numerusform>
            <numerusform>Polinoms tiek zīmēts ne vairāk kā %n punktiem.</numerusform>
        </translation>
    </message>
    <message>
        <source>polynomial</source>
        <extracomment>Legend label (noun): the interpolating polynomial drawn beside the spline.</extracomment>
        <translation>polinoms</translation>
    </message>
    <message>
        <source>spline</source>
        <extracomment>Legend label (noun): the spline.</extracomment>
        <translation>splains</translation>
    </message>
    <message>
        <source>Török&apos;s procedure needs evenly spaced knots: the classical system is drawn.</source>
        <translation>Töröka metodei vajag vienmērīgi izvietotus mezglus: attēlots klasiskās sistēmas atrisinājums.</translation>
    </message>
    <message>
        <source>Török&apos;s half-size system and the classical system agree: their slopes differ by at most %1.</source>
        <translation>Töröka uz pusi mazākā sistēma un klasiskā sistēma sakrīt: to atvasinājumi atšķiras ne vairāk kā par %1.</translation>
    </message>
    <message>
        <source>Add the function spline to the document</source>
        <translation>Pievienot funkcijas splainu dokumentam</translation>
    </message>
    <message numerus="yes">
        <source>Knots: give %n number(s), four more than the number of values.</source>
        <translation>
            <numerusform>Mezgli: ievadiet %n skaitli — par četriem vairāk, nekā ir vērtību.</numerusform>
            <numerusform>Mezgli: ievadiet %n skaitļus — par četriem vairāk, nekā ir vērtību.</numerusform>
            <numerusform>Mezgli: ievadiet %n skaitļu — par četriem vairāk, nekā ir vērtību.</numerusform>
        </translation>
    </message>
    <message>
        <source>Control values b: %1</source>
        <extracomment>b are the global B-spline&apos;s control values, as the course writes them (one per bell Bs).</extracomment>
        <translation>Kontrolvērtības b: %1</translation>
    </message>
    <message>
        <source>Török&apos;s half-size system and the classical system agree: their slopes differ by less than 10⁻¹⁵ (rounding).</source>
        <translation>Töröka uz pusi mazākā sistēma un klasiskā sistēma sakrīt: to atvasinājumi atšķiras mazāk nekā par 10⁻¹⁵ (noapaļošana).</translation>
    </message>
    <message>
        <source>P(%1) = %2</source>
        <extracomment>One value of the spline: P(1,5) = 0,075 (%1 is x, %2 the value).</extracomment>
        <translation>P(%1) = %2</translation>
    </message>
    <message>
        <source>Between the knots: %1</source>
        <extracomment>The spline&apos;s values halfway between the knots, e.g. &quot;P(1,5) = 0,075; P(2,5) = 1,175&quot;.</extracomment>
        <translation>Starp mezgliem: %1</translation>
    </message>
</context>
<context>
    <name>kontur::PieceEdits</name>
    <message>
        <source>There is no other open composite curve to join.</source>
        <translation>Nav citas nenoslēgtas saliktas līknes, ar ko to savienot.</translation>
    </message>
    <message>
        <source>No curve with fewer knots stays within that tolerance.</source>
        <translation>Nav līknes ar mazāk mezgla punktiem, kas iekļautos šajā precizitātē.</translation>
    </message>
    <message>
        <source>Type a tolerance greater than zero.</source>
        <translation>Ievadiet precizitāti, kas lielāka par nulli.</translation>
    </message>
    <message>
        <source>This works on composite curves that are not locked.</source>
        <translation>Tas darbojas tikai ar saliktām līknēm, kas nav bloķētas.</translation>
    </message>
    <message>
        <source>Make line</source>
        <translation>Iztaisnot segmentu</translation>
    </message>
    <message>
        <source>Join curves</source>
        <translation>Savienot līknes</translation>
    </message>
    <message>
        <source>Simplify curve</source>
        <translation>Vienkāršot līkni</translation>
    </message>
    <message>
        <source>Extend curve</source>
        <translation>Turpināt līkni</translation>
    </message>
</context>
<context>
    <name>kontur::PieceMarkEdits</name>
    <message>
        <source>A pattern piece is a closed curve: close the curve first.</source>
        <translation>Piegrieztnes detaļa ir slēgta līkne: vispirms aizveriet līkni.</translation>
    </message>
    <message>
        <source>Select a pattern piece first.</source>
        <translation>Vispirms atlasiet piegrieztnes detaļu.</translation>
    </message>
    <message>
        <source>Type how many to cut: a whole number from 1 up.</source>
        <translation>Ierakstiet, cik piegriezt: veselu skaitli no 1.</translation>
    </message>
    <message>
        <source>The two points are too close together: tap two points farther apart.</source>
        <translation>Abi punkti ir pārāk tuvu: pieskarieties diviem tālākiem punktiem.</translation>
    </message>
    <message>
        <source>There is no mark there.</source>
        <translation>Tur nav atzīmes.</translation>
    </message>
    <message>
        <source>Make a pattern piece</source>
        <translation>Padarīt par piegrieztnes detaļu</translation>
    </message>
    <message>
        <source>No longer a pattern piece</source>
        <translation>Vairs nav piegrieztnes detaļa</translation>
    </message>
    <message>
        <source>Set the piece&apos;s size</source>
        <translation>Iestatīt detaļas izmēru</translation>
    </message>
    <message>
        <source>Set how many to cut</source>
        <translation>Iestatīt, cik piegriezt</translation>
    </message>
    <message>
        <source>Set the piece&apos;s material</source>
        <translation>Iestatīt detaļas materiālu</translation>
    </message>
    <message>
        <source>Draw the grainline</source>
        <translation>Zīmēt diega virzienu</translation>
    </message>
    <message>
        <source>Place on fold</source>
        <translation>Likt uz locījuma</translation>
    </message>
    <message>
        <source>Add a notch</source>
        <translation>Pievienot iegriezumu</translation>
    </message>
    <message>
        <source>Move a notch</source>
        <translation>Pārvietot iegriezumu</translation>
    </message>
    <message>
        <source>Change a notch</source>
        <translation>Mainīt iegriezumu</translation>
    </message>
    <message>
        <source>Add a drill hole</source>
        <translation>Pievienot urbuma atzīmi</translation>
    </message>
    <message>
        <source>Move a drill hole</source>
        <translation>Pārvietot urbuma atzīmi</translation>
    </message>
    <message>
        <source>Delete a mark</source>
        <translation>Dzēst atzīmi</translation>
    </message>
</context>
<context>
    <name>kontur::PracticumPlot</name>
    <message>
        <source>The end points have the same x: there is no function segment.</source>
        <translation>Galapunktiem ir vienāds x: funkcijas segmenta nav.</translation>
    </message>
    <message>
        <source>A vertical guide vector has no slope dy/dx: a function segment needs one.</source>
        <translation>Vertikālam virziena vektoram nav slīpuma dy/dx: funkcijas segmentam tas vajadzīgs.</translation>
    </message>
    <message>
        <source>t = x1 − x0 = %1; k0 = %2; k1 = %3; a3 = %4; a4 = %5</source>
        <translation>t = x1 − x0 = %1; k0 = %2; k1 = %3; a3 = %4; a4 = %5</translation>
    </message>
    <message>
        <source>The end points coincide or a guide vector has no length.</source>
        <translation>Galapunkti sakrīt vai virziena vektoram nav garuma.</translation>
    </message>
    <message>
        <source>t2 = |P1 − P0| = %1; P0′ = %2; P1′ = %3; a3 = %4; a4 = %5</source>
        <translation>t2 = |P1 − P0| = %1; P0′ = %2; P1′ = %3; a3 = %4; a4 = %5</translation>
    </message>
    <message>
        <source>Two neighbouring points coincide or a guide vector has no length.</source>
        <translation>Divi blakus punkti sakrīt vai virziena vektoram nav garuma.</translation>
    </message>
    <message>
        <source>Chords T: %1
Tangents K: %2</source>
        <extracomment>Two lines of figures: %1 the chord lengths T, %2 the tangent lengths K of the segments (numbers).</extracomment>
        <translation>Hordas T: %1
Virziena vektori K: %2</translation>
    </message>
</context>
<context>
    <name>kontur::SeamWidths</name>
    <message>
        <source>The piece has no seam allowance yet: add one first.</source>
        <translation>Detaļai vēl nav šuves pielaides: vispirms pievienojiet to.</translation>
    </message>
    <message>
        <source>Tap a seam of the piece first.</source>
        <translation>Vispirms pieskarieties detaļas šuvei.</translation>
    </message>
    <message>
        <source>Type the seam allowance: a number from 0 up.</source>
        <translation>Ierakstiet šuves pielaidi: skaitli no 0.</translation>
    </message>
    <message>
        <source>The seam allowance cannot be that wide on this piece.</source>
        <translation>Šai detaļai šuves pielaide nevar būt tik plata.</translation>
    </message>
    <message>
        <source>Set a seam&apos;s allowance</source>
        <translation>Iestatīt šuves pielaidi</translation>
    </message>
    <message>
        <source>Set a hem&apos;s corners</source>
        <translation>Iestatīt apakšmalas stūrus</translation>
    </message>
</context>
<context>
    <name>kontur::TraceController</name>
    <message>
        <source>Calibrate background</source>
        <translation>Kalibrēt fonu</translation>
    </message>
    <message>
        <source>The tolerance must be a positive number.</source>
        <translation>Precizitātei jābūt pozitīvam skaitlim.</translation>
    </message>
    <message>
        <source>Draw along the contour with one finger, a stylus or the mouse.</source>
        <translation>Velciet gar kontūru ar vienu pirkstu, irbuli vai peli.</translation>
    </message>
    <message>
        <source>The stroke could not be fitted.</source>
        <translation>Vilkumu nevarēja aproksimēt.</translation>
    </message>
    <message>
        <source>Traced %1</source>
        <extracomment>Automatic name of a curve drawn freehand over the picture: %1 is a running number.</extracomment>
        <translation>Pārzīmētā līkne Nr. %1</translation>
    </message>
    <message>
        <source>Freehand curve</source>
        <translation>Ar brīvu roku zīmēta līkne</translation>
    </message>
    <message>
        <source>Load a background picture first.</source>
        <translation>Vispirms ielādējiet fona attēlu.</translation>
    </message>
    <message>
        <source>Tap a knot of the curve.</source>
        <translation>Pieskarieties līknes mezgla punktam.</translation>
    </message>
    <message>
        <source>Tap a curve.</source>
        <translation>Pieskarieties līknei.</translation>
    </message>
    <message>
        <source>Tap a second, different curve.</source>
        <translation>Pieskarieties otrai, citai līknei.</translation>
    </message>
    <message>
        <source>This kind of curve has no knots to measure between.</source>
        <translation>Šāda veida līknei nav mezgla punktu, starp kuriem mērīt.</translation>
    </message>
    <message>
        <source>These curves cannot be compared.</source>
        <translation>Šīs līknes nevar salīdzināt.</translation>
    </message>
    <message>
        <source>Tap two points on the picture first.</source>
        <translation>Vispirms pieskarieties diviem punktiem attēlā.</translation>
    </message>
    <message>
        <source>Type the real distance between the two points as a positive number.</source>
        <translation>Ievadiet reālo attālumu starp abiem punktiem kā pozitīvu skaitli.</translation>
    </message>
    <message>
        <source>The background is locked. Unlock it to calibrate again.</source>
        <translation>Fons ir bloķēts. Atbloķējiet to, lai kalibrētu no jauna.</translation>
    </message>
    <message>
        <source>Choose mm, cm or in.</source>
        <translation>Izvēlieties mm, cm vai collas.</translation>
    </message>
    <message>
        <source>The two points must be different.</source>
        <translation>Abiem punktiem jābūt atšķirīgiem.</translation>
    </message>
    <message>
        <source>Curve &quot;%1&quot; cannot be turned; calibrate without aligning.</source>
        <translation>Līkni „%1“ nevar pagriezt; kalibrējiet bez izlīdzināšanas.</translation>
    </message>
    <message>
        <source>Draw along the contour with one finger, a stylus or the mouse; two fingers zoom.</source>
        <translation>Velciet gar kontūru ar vienu pirkstu, irbuli vai peli; ar diviem pirkstiem var pietuvināt un attālināt.</translation>
    </message>
    <message>
        <source>Tap two points on the picture whose real distance you know.</source>
        <translation>Pieskarieties diviem attēla punktiem, kuru reālo attālumu zināt.</translation>
    </message>
    <message>
        <source>Type the real distance between the two points.</source>
        <translation>Ievadiet reālo attālumu starp abiem punktiem.</translation>
    </message>
    <message>
        <source>Tap two points to measure the straight distance.</source>
        <translation>Pieskarieties diviem punktiem, lai izmērītu taisno attālumu.</translation>
    </message>
    <message>
        <source>Tap two knots of one curve to measure the length along it.</source>
        <translation>Pieskarieties diviem vienas līknes mezgla punktiem, lai izmērītu garumu gar to.</translation>
    </message>
    <message>
        <source>Tap the traced curve, then the reference curve.</source>
        <translation>Pieskarieties pārzīmētajai līknei, tad etalonlīknei.</translation>
    </message>
    <message>
        <source>Drag the picture to move it; two fingers zoom.</source>
        <translation>Velciet attēlu, lai to pārvietotu; ar diviem pirkstiem var pietuvināt un attālināt.</translation>
    </message>
    <message>
        <source>The background is locked. Unlock it to move it.</source>
        <translation>Fons ir bloķēts. Atbloķējiet to, lai pārvietotu.</translation>
    </message>
    <message>
        <source>Tap the four corners of the rectangle first.</source>
        <translation>Vispirms pieskarieties četriem taisnstūra stūriem.</translation>
    </message>
    <message>
        <source>Type the rectangle&apos;s width and height as positive numbers.</source>
        <translation>Ievadiet taisnstūra platumu un augstumu kā pozitīvus skaitļus.</translation>
    </message>
    <message>
        <source>The picture has a perspective calibration. Clear it to calibrate by two points.</source>
        <translation>Attēlam ir perspektīvas kalibrēšana. Noņemiet to, lai kalibrētu pēc diviem punktiem.</translation>
    </message>
    <message>
        <source>There the corners would not make a rectangle; the corner stays where it was.</source>
        <translation>Tur stūri neveidotu taisnstūri; stūris paliek, kur bija.</translation>
    </message>
    <message>
        <source>Drag a corner onto the rectangle&apos;s corner in the picture, or tap four new corners.</source>
        <translation>Velciet stūri uz taisnstūra stūri attēlā vai pieskarieties četriem jauniem stūriem.</translation>
    </message>
    <message>
        <source>Tap the four corners of a rectangle whose size you know, in any order.</source>
        <translation>Jebkurā secībā pieskarieties tāda taisnstūra četriem stūriem, kura izmērus zināt.</translation>
    </message>
    <message>
        <source>Choose the rectangle&apos;s size and apply; drag a corner to refine it.</source>
        <translation>Izvēlieties taisnstūra izmēru un nospiediet „Lietot“; velciet stūri, lai to precizētu.</translation>
    </message>
    <message>
        <source>Calibrate perspective</source>
        <translation>Kalibrēt perspektīvu</translation>
    </message>
    <message>
        <source>Refine perspective corner</source>
        <translation>Precizēt perspektīvas stūri</translation>
    </message>
    <message>
        <source>Outline %1</source>
        <extracomment>Automatic name of a curve traced along a piece&apos;s outline in the photo: %1 is a running number.</extracomment>
        <translation>Kontūra %1</translation>
    </message>
    <message>
        <source>Trace outline</source>
        <translation>Pārzīmēt kontūru</translation>
    </message>
    <message>
        <source>The background picture cannot be read.</source>
        <translation>Fona attēlu nevar nolasīt.</translation>
    </message>
    <message>
        <source>No sheet found in the picture (a white rectangle with four straight, clear edges). Tap its four corners instead.</source>
        <translation>Attēlā nav atrasta lapa (balts taisnstūris ar četrām taisnām, skaidrām malām). Tā vietā pieskarieties tās četriem stūriem.</translation>
    </message>
    <message>
        <source>No corner found near the mark; it stays where you dropped it.</source>
        <translation>Pie atzīmes stūris nav atrasts; tā paliek, kur to nolikāt.</translation>
    </message>
    <message>
        <source>The calibration may be off by %1 mm at the far side of the picture. Find the sheet again or refine its corners.</source>
        <translation>Kalibrēšana attēla tālākajā malā var kļūdīties par %1 mm. Atrodiet lapu vēlreiz vai precizējiet tās stūrus.</translation>
    </message>
    <message>
        <source>No pattern piece found there. Tap inside a piece that stands out from the table.</source>
        <translation>Tur nav atrasta neviena piegrieztnes detaļa. Pieskarieties tādas detaļas iekšpusē, kas izceļas uz galda fona.</translation>
    </message>
    <message>
        <source>The outline could not be made into a curve.</source>
        <translation>Kontūru nevarēja pārvērst līknē.</translation>
    </message>
    <message>
        <source>No edge found along the stroke; it was fitted as drawn.</source>
        <translation>Gar vilkumu mala nav atrasta; tas aproksimēts, kā uzzīmēts.</translation>
    </message>
    <message>
        <source>Tap inside a pattern piece on the picture to trace its outline.</source>
        <translation>Pieskarieties piegrieztnes detaļas iekšpusē attēlā, lai pārzīmētu tās kontūru.</translation>
    </message>
    <message>
        <source>The four points are not the corners of a rectangle seen in the picture. Tap them again.</source>
        <translation>Šie četri punkti nav attēlā redzama taisnstūra stūri. Pieskarieties tiem vēlreiz.</translation>
    </message>
    <message>
        <source>The sheet in the picture is not flat: its edges bend. Lay it flat and take the photo again, or tap its four corners.</source>
        <translation>Attēlā redzamā lapa nav plakana: tās malas ir izliektas. Novietojiet to līdzeni un nofotografējiet vēlreiz vai pieskarieties tās četriem stūriem.</translation>
    </message>
    <message>
        <source>The rectangle found is about %1 : 1, the chosen one %2 : 1. Choose the sheet&apos;s size, or tap its four corners.</source>
        <extracomment>%1 and %2 are proportions, long side to short side, such as 2.35 and 1.41.</extracomment>
        <translation>Atrastā taisnstūra malu attiecība ir aptuveni %1 : 1, izvēlētā — %2 : 1. Izvēlieties lapas izmēru vai pieskarieties tās četriem stūriem.</translation>
    </message>
</context>
<context>
    <name>kontur::cli</name>
    <message>
        <source>%1: several curves in the file (%2); the points of the first one (line %3) are read</source>
        <translation>%1: failā ir vairākas līknes (%2); tiek nolasīti pirmās līknes (%3. rinda) punkti</translation>
    </message>
    <message>
        <source>unexpected argument &quot;%1&quot;</source>
        <translation>negaidīts arguments „%1“</translation>
    </message>
    <message>
        <source>--in FILE is required</source>
        <translation>nepieciešams --in FAILS</translation>
    </message>
    <message>
        <source>Fit a cubic Bézier curve to points (one &quot;x y&quot; per line).</source>
        <translation>Pielāgot kubisku Bezjē līkni punktiem (viens „x y“ katrā rindā).</translation>
    </message>
    <message>
        <source>interpolate (exactly 4 points) or least-squares.</source>
        <translation>interpolate (tieši 4 punkti) vai least-squares.</translation>
    </message>
    <message>
        <source>uniform, chord or centripetal.</source>
        <translation>uniform, chord vai centripetal.</translation>
    </message>
    <message>
        <source>The points file.</source>
        <translation>Punktu fails.</translation>
    </message>
    <message>
        <source>unknown --method &quot;%1&quot; (interpolate or least-squares)</source>
        <translation>nezināms --method „%1“ (interpolate vai least-squares)</translation>
    </message>
    <message>
        <source>unknown --param &quot;%1&quot; (uniform, chord or centripetal)</source>
        <translation>nezināms --param „%1“ (uniform, chord vai centripetal)</translation>
    </message>
    <message>
        <source>--reparameterize needs a non-negative integer</source>
        <translation>opcijai --reparameterize vajag nenegatīvu veselu skaitli</translation>
    </message>
    <message>
        <source>%1: %2 points; interpolate needs exactly 4</source>
        <extracomment>%1 is a file name, %2 the number of points in it.</extracomment>
        <translation>%1: punktu skaits %2; metodei interpolate vajag tieši 4</translation>
    </message>
    <message>
        <source>The control points file.</source>
        <translation>Kontrolpunktu fails.</translation>
    </message>
    <message>
        <source>Elevate the degree R times.</source>
        <translation>Paaugstināt pakāpi R reizes.</translation>
    </message>
    <message>
        <source>Evaluate at t1,t2,…</source>
        <translation>Aprēķināt punktos t1, t2, …</translation>
    </message>
    <message>
        <source>Arc length to this absolute accuracy.</source>
        <translation>Loka garums ar šo absolūto precizitāti.</translation>
    </message>
    <message>
        <source>Nearest point to x,y.</source>
        <translation>Līknes punkts, kas ir vistuvāk punktam x,y.</translation>
    </message>
    <message>
        <source>The tight bounding box.</source>
        <translation>Mazākais aptverošais taisnstūris.</translation>
    </message>
    <message>
        <source>--elevate needs an integer from 0 to 10000</source>
        <translation>opcijai --elevate vajag veselu skaitli no 0 līdz 10000</translation>
    </message>
    <message>
        <source>--at needs numbers separated by commas</source>
        <translation>opcijai --at vajag skaitļus, atdalītus ar komatiem</translation>
    </message>
    <message>
        <source>--length needs a positive accuracy</source>
        <translation>opcijai --length vajag pozitīvu precizitāti</translation>
    </message>
    <message>
        <source>--nearest needs x,y</source>
        <translation>opcijai --nearest vajag x,y</translation>
    </message>
    <message>
        <source>Build the composite curve through the knots in the file.</source>
        <translation>Izveidot salikto līkni caur failā dotajiem mezgla punktiem.</translation>
    </message>
    <message>
        <source>The knots file.</source>
        <translation>Mezgla punktu fails.</translation>
    </message>
    <message>
        <source>Close the curve.</source>
        <translation>Noslēgt līkni.</translation>
    </message>
    <message>
        <source>Relative tolerance of the continuity report (default 1e-9).</source>
        <translatorcomment>pielaide kept here: a numeric tolerance of the command line, where no one reads it as the seam allowance; the app says precizitāte.</translatorcomment>
        <translation>Nepārtrauktības atskaites relatīvā pielaide (noklusējums 1e-9).</translation>
    </message>
    <message>
        <source>--tolerance needs a non-negative number</source>
        <translation>opcijai --tolerance vajag nenegatīvu skaitli</translation>
    </message>
    <message numerus="yes">
        <source>expected %n file name(s), got %1</source>
        <translation>
            <numerusform>gaidīts %n faila nosaukums, saņemti %1</numerusform>
            <numerusform>gaidīti %n failu nosaukumi, saņemti %1</numerusform>
            <numerusform>gaidīts %n failu nosaukumu, saņemti %1</numerusform>
        </translation>
    </message>
    <message>
        <source>The input file.</source>
        <translation>Ievades fails.</translation>
    </message>
    <message>
        <source>The output file.</source>
        <translation>Izvades fails.</translation>
    </message>
    <message>
        <source>Kind of curve for points without one (default composite).</source>
        <translation>Līknes veids punktiem, kuriem tas nav norādīts (noklusējums composite).</translation>
    </message>
    <message>
        <source>Parameterization for fitted kinds (default chord).</source>
        <translation>Parametrizācija pielāgotajiem veidiem (noklusējums chord).</translation>
    </message>
    <message>
        <source>Write only curve N (0-based).</source>
        <translation>Rakstīt tikai līkni N (numurējot no 0).</translation>
    </message>
    <message>
        <source>unknown --kind &quot;%1&quot;</source>
        <translation>nezināms --kind „%1“</translation>
    </message>
    <message>
        <source>--curve needs a curve number from 0 to %1</source>
        <translation>opcijai --curve vajag līknes numuru no 0 līdz %1</translation>
    </message>
    <message>
        <source>Describe the curves of a file as JSON: kinds, point counts, lengths, bounding boxes, continuity.</source>
        <translation>Aprakstīt faila līknes JSON formātā: veidi, punktu skaits, garumi, aptverošie taisnstūri, nepārtrauktība.</translation>
    </message>
    <message>
        <source>Absolute accuracy of the lengths (default 1e-9).</source>
        <translation>Garumu absolūtā precizitāte (noklusējums 1e-9).</translation>
    </message>
    <message>
        <source>--accuracy needs a positive number</source>
        <translation>opcijai --accuracy vajag pozitīvu skaitli</translation>
    </message>
    <message>
        <source>
For every command:
  --lang CODE  the language of help and messages: %1 (default: the system&apos;s)
</source>
        <translation>
Visām komandām:
  --lang KODS  palīdzības un ziņojumu valoda: %1 (noklusējums: sistēmas valoda)
</translation>
    </message>
    <message>
        <source>kontur-cli: unknown command &quot;%1&quot;</source>
        <translation>kontur-cli: nezināma komanda „%1“</translation>
    </message>
    <message>
        <source>%1:%2: expected two numbers &quot;x y&quot;, got &quot;%3&quot;</source>
        <translation>%1:%2: gaidīti divi skaitļi „x y“, saņemts „%3“</translation>
    </message>
    <message>
        <source>%1: cannot read the file: %2</source>
        <translation>%1: nevar nolasīt failu: %2</translation>
    </message>
    <message>
        <source>The family (see above).</source>
        <translation>Saime (skatīt augstāk).</translation>
    </message>
    <message>
        <source>uniform, chord (default) or centripetal.</source>
        <translation>uniform, chord (noklusējums) vai centripetal.</translation>
    </message>
    <message>
        <source>A function spline y(x) over the points&apos; increasing x; --at then takes x values and points are [x, y].</source>
        <translation>Funkcijas splains y(x) pēc punktu x vērtībām augošā secībā; tad --at pieņem x vērtības un punkti ir [x, y].</translation>
    </message>
    <message>
        <source>Start tangent x,y (clamped, global-bspline; default the first chord).</source>
        <translation>Sākuma virziena vektors x,y (clamped, global-bspline; noklusējums pirmā horda).</translation>
    </message>
    <message>
        <source>End tangent x,y (clamped, global-bspline; default the last chord).</source>
        <translation>Beigu virziena vektors x,y (clamped, global-bspline; noklusējums pēdējā horda).</translation>
    </message>
    <message>
        <source>--kind must be one of %1</source>
        <translation>opcijai --kind vajag vienu no: %1</translation>
    </message>
    <message>
        <source>--%1 needs x,y</source>
        <translation>opcijai --%1 vajag x,y</translation>
    </message>
    <message>
        <source>--order needs an integer</source>
        <translation>opcijai --order vajag veselu skaitli</translation>
    </message>
    <message>
        <source>a function B-spline takes a knot vector and control values, not points: drop --function</source>
        <translation>funkcijas B-splains pieņem mezglu vektoru un kontrolvērtības, nevis punktus: noņemiet --function</translation>
    </message>
    <message>
        <source>at least 2 points are needed</source>
        <translation>vajag vismaz 2 punktus</translation>
    </message>
    <message>
        <source>a vertical or zero end tangent has no slope</source>
        <translation>vertikālam vai nulles beigu virziena vektoram nav slīpuma</translation>
    </message>
    <message>
        <source>--knots needs open-uniform, uniform or numbers separated by commas</source>
        <translation>opcijai --knots vajag open-uniform, uniform vai skaitļus, atdalītus ar komatiem</translation>
    </message>
    <message>
        <source>could not compute &quot;%1&quot; as a finite number: the numbers involved exceed the range of double precision</source>
        <translation>nevarēja aprēķināt „%1“ kā galīgu skaitli: iesaistītie skaitļi pārsniedz dubultās precizitātes diapazonu</translation>
    </message>
    <message>
        <source>unknown --solver &quot;%1&quot; (classical or torok)</source>
        <translation>nezināms --solver „%1“ (classical vai torok)</translation>
    </message>
    <message>
        <source>--solver is for --kind clamped</source>
        <translation>opcija --solver ir paredzēta tikai kopā ar --kind clamped</translation>
    </message>
    <message>
        <source>Török&apos;s procedure needs evenly spaced knots: use --param uniform or --function</source>
        <translation>Töröka metodei vajag vienmērīgi izvietotus mezglus: izmantojiet --param uniform vai --function</translation>
    </message>
    <message>
        <source>a contour curve is drawn through its points in the plane: drop --function</source>
        <translation>kontūrlīkne tiek veidota pēc punktiem plaknē: noņemiet --function</translation>
    </message>
    <message>
        <source>--paper needs a4 or letter</source>
        <translation>opcijai --paper vajag a4 vai letter</translation>
    </message>
    <message>
        <source>--orientation needs auto, portrait or landscape</source>
        <translation>opcijai --orientation vajag auto, portrait vai landscape</translation>
    </message>
    <message>
        <source>--overlap needs millimetres from 0 to 50</source>
        <translation>opcijai --overlap vajag milimetrus no 0 līdz 50</translation>
    </message>
    <message>
        <source>PDF: the paper, a4 or letter (default a4).</source>
        <translation>PDF: papīrs, a4 vai letter (noklusējums a4).</translation>
    </message>
    <message>
        <source>PDF: auto (the one with fewer pages), portrait or landscape (default auto).</source>
        <translation>PDF: auto (tā, kurai vajag mazāk lapu), portrait vai landscape (noklusējums auto).</translation>
    </message>
    <message>
        <source>PDF: millimetres neighbouring pages repeat (default 10).</source>
        <translation>PDF: blakus lapu pārklāšanās milimetros (noklusējums 10).</translation>
    </message>
    <message>
        <source>Add seam allowances: the offset of each curve (or of curve N) at a distance, written after the
input&apos;s curves. In a .kontur output each allowance keeps its link to its curve.</source>
        <translation>Pievienot šuvju pielaides: katras līknes (vai līknes N) nobīdi dotajā attālumā, ierakstītu aiz
ievades līknēm. .kontur izvadē katra pielaide saglabā saiti ar savu līkni.</translation>
    </message>
    <message>
        <source>Offset only curve N (0-based).</source>
        <translation>Nobīdīt tikai līkni N (numurējot no 0).</translation>
    </message>
    <message>
        <source>Distance in the document&apos;s units (default 1 cm).</source>
        <translation>Attālums dokumenta mērvienībās (noklusējums 1 cm).</translation>
    </message>
    <message>
        <source>outside, inside, left or right (default outside).</source>
        <translation>outside, inside, left vai right (noklusējums outside).</translation>
    </message>
    <message>
        <source>Corners: miter, bevel or round (default miter).</source>
        <translation>Stūri: miter, bevel vai round (noklusējums miter).</translation>
    </message>
    <message>
        <source>Longest miter from the corner (default 3 cm).</source>
        <translation>Lielākais smailā stūra garums no stūra (noklusējums 3 cm).</translation>
    </message>
    <message>
        <source>Largest error of the offset (default 0.05 mm).</source>
        <translation>Lielākā nobīdes kļūda (noklusējums 0,05 mm).</translation>
    </message>
    <message>
        <source>--distance needs a positive number</source>
        <translation>opcijai --distance vajag pozitīvu skaitli</translation>
    </message>
    <message>
        <source>--miter-limit needs a number of at least 0</source>
        <translation>opcijai --miter-limit vajag skaitli, kas nav mazāks par 0</translation>
    </message>
    <message>
        <source>--tolerance needs a positive number</source>
        <translation>opcijai --tolerance vajag pozitīvu skaitli</translation>
    </message>
    <message>
        <source>unknown --side &quot;%1&quot;</source>
        <translation>nezināms --side „%1“</translation>
    </message>
    <message>
        <source>unknown --join &quot;%1&quot;</source>
        <translation>nezināms --join „%1“</translation>
    </message>
    <message>
        <source>%1: unknown file type (%2)</source>
        <translation>%1: nezināms faila tips (%2)</translation>
    </message>
    <message>
        <source>Convert between points text (.txt), CSV, Kontur documents (.kontur), SVG and DXF, by extension.
A .txt output is appended to, never overwritten; other outputs are replaced atomically.
A .pdf output prints the visible curves at true size over A4 or Letter pages (a first page with
a 10 cm test square and the overview, then the pages to tape together); the document is kept
inside, so a PDF Kontur wrote converts back.</source>
        <translation>Pārvērst starp punktu tekstu (.txt), CSV, Kontur dokumentiem (.kontur), SVG un DXF pēc paplašinājuma.
.txt izvade tiek papildināta, nekad pārrakstīta; citas izvades tiek aizstātas atomiski.
.pdf izvade izdrukā redzamās līknes īstajā izmērā uz A4 vai Letter lapām (pirmā lapa ar 10 cm
kontrolkvadrātu un pārskatu, tad salīmējamās lapas); dokuments tiek saglabāts tajā, tāpēc Kontur
rakstītu PDF var pārvērst atpakaļ.</translation>
    </message>
    <message>
        <source>DXF output: spline (exact Bézier control points, default) or polyline (flattened).</source>
        <translation>DXF izvade: spline (splaini ar precīziem Bezjē kontrolpunktiem, noklusējums) vai polyline (lauztas līnijas).</translation>
    </message>
    <message>
        <source>DXF polyline output: largest distance from the curves, in the document&apos;s units (default 0.05 mm).</source>
        <translation>DXF izvade ar lauztām līnijām: lielākais attālums no līknēm dokumenta mērvienībās (noklusējums 0,05 mm).</translation>
    </message>
    <message>
        <source>unknown --dxf &quot;%1&quot; (spline or polyline)</source>
        <translation>nezināms --dxf „%1“ (spline — splaini, vai polyline — lauztas līnijas)</translation>
    </message>
    <message>
        <source>A .txt, .csv, .kontur, .svg or .dxf file.</source>
        <translation>.txt, .csv, .kontur, .svg vai .dxf fails.</translation>
    </message>
    <message>
        <source>The photo (PNG, JPEG, PGM, ...).</source>
        <translation>Fotoattēls (PNG, JPEG, PGM, ...).</translation>
    </message>
    <message>
        <source>The sheet&apos;s size: a4, a3, letter or WxH with mm (default), cm or in.</source>
        <translation>Lapas izmērs: a4, a3, letter vai WxH ar mm (noklusējums), cm vai in.</translation>
    </message>
    <message>
        <source>Approximate corners in photo pixels, x,y;x,y;x,y;x,y in any order: the edges are searched near them.</source>
        <translation>Stūru aptuvenās koordinātas fotoattēla pikseļos, x,y;x,y;x,y;x,y jebkurā secībā: malas tiek meklētas to tuvumā.</translation>
    </message>
    <message>
        <source>--sheet needs a4, a3, letter or WxH[mm|cm|in], got &quot;%1&quot;</source>
        <translation>opcijai --sheet vajag a4, a3, letter vai WxH[mm|cm|in], saņemts „%1“</translation>
    </message>
    <message>
        <source>--corners needs four points x,y separated by semicolons or spaces</source>
        <translation>opcijai --corners vajag četrus punktus x,y, atdalītus ar semikoliem vai atstarpēm</translation>
    </message>
    <message>
        <source>%1: cannot read the photo</source>
        <translation>%1: nevar nolasīt fotoattēlu</translation>
    </message>
    <message>
        <source>Trace a pattern photographed beside a reference sheet: the sheet is found (its corners to a
fraction of a pixel), the photo rectified into the sheet&apos;s plane and every pattern piece&apos;s outline
written as a closed composite curve in mm to OUT.kontur, with the photo as its calibrated
background. --json prints the corners, the calibration&apos;s estimated error and each curve&apos;s knots.</source>
        <translation>Pārzīmēt piegrieztni, kas nofotografēta blakus atskaites lapai: lapa tiek atrasta (tās stūri ar
pikseļa daļas precizitāti), foto iztaisnots lapas plaknē un katras piegrieztnes detaļas kontūra
ierakstīta OUT.kontur kā slēgta salikta līkne milimetros, ar foto kā kalibrētu fona attēlu.
--json izvada stūrus, kalibrēšanas aptuveno kļūdu un katras līknes mezgla punktus.</translation>
    </message>
    <message>
        <source>The document to write (.kontur).</source>
        <translation>Rakstāmais dokuments (.kontur).</translation>
    </message>
    <message>
        <source>Print the sheet&apos;s corners, the calibration error and the outlines&apos; knots as JSON.</source>
        <translation>Izvadīt lapas stūrus, kalibrēšanas kļūdu un kontūru mezgla punktus kā JSON.</translation>
    </message>
    <message>
        <source>trace needs an output file OUT.kontur, or --json for the sheet&apos;s corners</source>
        <translation>pārzīmēšanai (trace) vajadzīgs izvades fails OUT.kontur vai --json lapas stūriem</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1: curve %2: %3</source>
        <translation>%1: līkne %2: %3</translation>
    </message>
    <message>
        <source>no such file</source>
        <translation>šāda faila nav</translation>
    </message>
    <message>
        <source>its symbolic links form a loop</source>
        <translation>tā simboliskās saites veido cilpu</translation>
    </message>
    <message>
        <source>permission denied</source>
        <translation>piekļuve liegta</translation>
    </message>
    <message>
        <source>it is a folder, not a file</source>
        <translation>tā ir mape, nevis fails</translation>
    </message>
    <message>
        <source>it is a named pipe (FIFO), not a regular file</source>
        <translation>tas ir nosaukts kanāls (FIFO), nevis parasts fails</translation>
    </message>
    <message>
        <source>it is a device, not a regular file</source>
        <translation>tā ir ierīce, nevis parasts fails</translation>
    </message>
    <message>
        <source>it is not a regular file</source>
        <translation>tas nav parasts fails</translation>
    </message>
    <message>
        <source>%1: a CSV file holds the points of one curve; the input has %2: choose one with --curve N</source>
        <translation>%1: CSV fails satur vienas līknes punktus; ievadē ir %2: izvēlieties vienu ar --curve N</translation>
    </message>
    <message>
        <source>%1: unknown language &quot;%2&quot;; choose one of: %3.</source>
        <extracomment>%1 is the program (kontur or kontur-cli), %2 the language code asked for, %3 the codes there are.</extracomment>
        <translation>%1: nezināma valoda „%2“; izvēlieties vienu no: %3.</translation>
    </message>
    <message>
        <source>Rounds of parameter correction (default 0: the parameters are used as computed).</source>
        <translation>Parametru korekcijas iterāciju skaits (noklusējums 0: parametrus izmanto tādus, kādi aprēķināti).</translation>
    </message>
    <message>
        <source>%1: %2 points; a least-squares cubic needs at least 4</source>
        <translation>%1: punktu skaits %2; mazāko kvadrātu kubiskajai līknei vajag vismaz 4</translation>
    </message>
    <message>
        <source>Work with the Bézier curve whose control points are in the file. Prints the control points (JSON key control_points) when --elevate is given or when nothing else is asked for.</source>
        <translation>Darbs ar Bezjē līkni, kuras kontrolpunkti ir failā. Izvada kontrolpunktus (JSON atslēga control_points), ja dots --elevate vai ja nekas cits nav prasīts.</translation>
    </message>
    <message>
        <source>%1: %2 points; a Bézier curve needs at least 2</source>
        <extracomment>%1 is a file name, %2 the number of points in it.</extracomment>
        <translation>%1: punktu skaits %2; Bezjē līknei vajag vismaz 2</translation>
    </message>
    <message>
        <source>%1: %2 points; a closed composite curve needs at least 3</source>
        <extracomment>%1 is a file name, %2 the number of points in it.</extracomment>
        <translation>%1: punktu skaits %2; slēgtai saliktai līknei vajag vismaz 3</translation>
    </message>
    <message>
        <source>%1: %2 points; a composite curve needs at least 2</source>
        <translation>%1: punktu skaits %2; saliktai līknei vajag vismaz 2</translation>
    </message>
    <message>
        <source>clamped on evenly spaced knots (--function over evenly spaced x, or --param uniform): classical (default, k - 2 unknowns) or torok (Török&apos;s half-size system); prints the JSON key &quot;solverDifference&quot;: the largest difference of the derivatives from the other solver.</source>
        <translation>clamped ar vienmērīgi izvietotiem mezgliem (--function ar vienmērīgi izvietotiem x vai --param uniform): classical (noklusējums, k - 2 nezināmie) vai torok (Töröka uz pusi mazākā sistēma); izvada JSON atslēgu &quot;solverDifference&quot; — lielāko atvasinājumu atšķirību no otras metodes.</translation>
    </message>
    <message>
        <source>Evaluate at u1,u2,… (a negative first value needs the = form: --at=-1,0.5).</source>
        <translation>Aprēķināt punktos u1, u2, … (ja pirmā vērtība ir negatīva, rakstiet ar =: --at=-1,0.5).</translation>
    </message>
    <message>
        <source>Usage: kontur-cli &lt;command&gt; [options]   (kontur-cli &lt;command&gt; --help for its options)
Kontur command-line tool: Bézier curves and splines without a window.

Commands:
  fit        cubic through 4 points or least-squares cubic through n &gt;= 4 points
  bezier     evaluate, elevate, measure and query a Bézier curve of any degree
  composite  the composite curve through knots, with its continuity report
  spline     a curve of any kind through points, built as the app builds it (bezier,
             composite, natural, clamped, hermite, bspline, function-spline, contour, …)
  convert    convert IN OUT between points text (.txt), CSV, .kontur, SVG, DXF and PDF (by
             extension; a PDF output is the pattern printed at true size)
  info       the curves of a file as JSON: kinds, lengths, bounding box, continuity
  offset     seam allowances: offset curves IN OUT at a distance, outside or inside
  trace      trace a pattern photographed beside a reference sheet into a document in mm
  bench      time an operation of the geometry core (for developers)

Input files hold one &quot;x y&quot; pair per line; &apos;#&apos; starts a comment. Output is JSON on stdout;
errors go to stderr with exit code 1 (bad input) or 2 (bad usage).
</source>
        <translation>Lietošana: kontur-cli &lt;komanda&gt; [opcijas]   (kontur-cli &lt;komanda&gt; --help parāda tās opcijas)
Kontur komandrindas rīks: Bezjē līknes un splaini bez loga.

Komandas:
  fit        kubiska līkne caur 4 punktiem vai mazāko kvadrātu kubiska līkne caur n &gt;= 4 punktiem
  bezier     jebkuras pakāpes Bezjē līknes aprēķins, pakāpes paaugstināšana, mērīšana un vaicājumi
  composite  salikta līkne caur mezgla punktiem ar nepārtrauktības atskaiti
  spline     jebkura veida līkne caur punktiem, veidota tāpat kā lietotnē (bezier,
             composite, natural, clamped, hermite, bspline, function-spline, contour, …)
  convert    pārvērst IN OUT starp punktu tekstu (.txt), CSV, .kontur, SVG, DXF un PDF (pēc paplašinājuma;
             PDF izvade ir piegrieztne, izdrukāta īstajā izmērā)
  info       faila līknes JSON formātā: veidi, garumi, aptverošais taisnstūris, nepārtrauktība
  offset     šuvju pielaides: līkņu nobīde IN OUT dotajā attālumā, ārpusē vai iekšpusē
  trace      pārzīmēt piegrieztni, kas nofotografēta blakus atskaites lapai, dokumentā milimetros
  bench      izmērīt ģeometrijas kodola operācijas laiku (izstrādātājiem)

Ievades failos katrā rindā ir viens pāris „x y“; &apos;#&apos; sāk komentāru. Izvade ir JSON uz stdout;
kļūdas tiek rakstītas stderr ar izejas kodu 1 (nederīga ievade) vai 2 (nepareiza lietošana).
</translation>
    </message>
    <message>
        <source>The curve of a kind through the points of a file (one &quot;x y&quot; per line), built by the same function as the app&apos;s curve of that kind: bezier (the points are its control points), interpolating, least-squares, composite, natural, clamped, not-a-knot, periodic, catmull-rom, hermite, bspline (the points are its control polygon), global-bspline, polynomial, function-spline (the natural spline y(x)) or contour (Bézier pieces joined at the midpoints of pairs of points). Prints {&quot;knots&quot;: parameter of each point (the knot vector for bspline; 0, 1, … one per piece for bezier, interpolating, least-squares, composite and contour), &quot;segments&quot;: Bézier control points of each piece, &quot;points&quot;: [u, x, y] at --at}. Parameters are unnormalised: uniform 0, 1, 2, …; chord the cumulative chord length; centripetal the cumulative square roots.</source>
        <translation>Līkne caur faila punktiem (viens „x y“ katrā rindā), veidota ar to pašu funkciju kā šī veida līkne lietotnē: bezier (punkti ir tās kontrolpunkti), interpolating, least-squares, composite, natural, clamped, not-a-knot, periodic, catmull-rom, hermite, bspline (punkti ir tā kontrolpunktu lauztā līnija), global-bspline, polynomial, function-spline (dabiskais splains y(x)) vai contour (Bezjē posmi, kas savienoti punktu pāru viduspunktos). Izvada {&quot;knots&quot;: katra punkta parametrs (bspline gadījumā mezglu vektors; bezier, interpolating, least-squares, composite un contour gadījumā 0, 1, …, viens katram posmam), &quot;segments&quot;: katra posma Bezjē kontrolpunkti, &quot;points&quot;: [u, x, y] punktos, kas doti ar --at}. Parametri nav normēti: uniform 0, 1, 2, …; chord — hordu garumu kumulatīvā summa; centripetal — kvadrātsakņu kumulatīvā summa.</translation>
    </message>
    <message>
        <source>B-spline order k, 2 to 10 (default as in the app: 4, cubic, or the number of points when fewer).</source>
        <translation>B-splaina kārta k, no 2 līdz 10 (noklusējums kā lietotnē: 4, kubisks, vai punktu skaits, ja to ir mazāk).</translation>
    </message>
    <message>
        <source>B-spline knot vector: open-uniform (default, the app&apos;s knots), uniform, or u0,u1,… (n + k values).</source>
        <translation>B-splaina mezglu vektors: open-uniform (noklusējums, lietotnes mezgli), uniform vai u0,u1,… (n + k vērtības).</translation>
    </message>
    <message>
        <source>hermite: a file with one tangent &quot;x y&quot; per point (default Catmull–Rom tangents, as in the app).</source>
        <translation>hermite: fails ar vienu virziena vektoru „x y“ katram punktam (noklusējums Katmula–Roma virziena vektori, kā lietotnē).</translation>
    </message>
    <message>
        <source>composite: the closed curve (as Close curve makes it in the app).</source>
        <translation>composite: slēgta līkne (kā to lietotnē veido „Noslēgt līkni“).</translation>
    </message>
    <message>
        <source>--closed is for --kind composite (the periodic spline is closed by its kind)</source>
        <translation>opcija --closed ir paredzēta tikai kopā ar --kind composite (periodiskais splains ir slēgts jau pēc sava veida)</translation>
    </message>
    <message>
        <source>%1: not drawn: %2</source>
        <translation>%1: nav uzzīmēts: %2</translation>
    </message>
    <message>
        <source>Units of a DXF that names none: mm, cm, in or px (default px).</source>
        <translation>Mērvienības DXF failam, kurā tās nav norādītas: mm, cm, in vai px (noklusējums px).</translation>
    </message>
    <message>
        <source>--units needs mm, cm, in or px</source>
        <translation>opcijai --units vajag mm, cm, in vai px</translation>
    </message>
    <message>
        <source>DXF output as ASTM D6673 (AAMA) garment pieces: a block per closed curve, its cut line (its seam allowance, if any) and texts on layer 1, sew line 14, notches 4, mirror line 6, the piece&apos;s own grain line 7 (none if it has none), internal lines 8, drill holes 13; polylines unless --dxf spline is given.</source>
        <translation>DXF izvade kā ASTM D6673 (AAMA) apģērbu detaļas: bloks katrai noslēgtai līknei, tās griešanas līnija (šuves pielaide, ja tāda ir) un teksti 1. slānī, šuves līnija 14. slānī, iegriezumi 4. slānī, locījuma (spoguļa) līnija 6. slānī, detaļas pašas diega virziena līnija 7. slānī (nekāda, ja detaļai tās nav), iekšējās līnijas 8. slānī, urbuma atzīmes 13. slānī; lauztas līnijas, ja vien nav dots --dxf spline (splaini).</translation>
    </message>
    <message>
        <source>%1: the sheet is not flat (its edges are not straight); lay it flat and photograph it again, or give its four corners roughly with --corners x,y;x,y;x,y;x,y</source>
        <translation>%1: lapa nav plakana (tās malas nav taisnas); novietojiet to līdzeni un nofotografējiet vēlreiz vai norādiet tās četrus stūrus aptuveni ar --corners x,y;x,y;x,y;x,y</translation>
    </message>
    <message>
        <source>%1: the rectangle found is about %2 : 1, not %3 (%4 : 1); give the sheet&apos;s size with --sheet, or its four corners roughly with --corners x,y;x,y;x,y;x,y</source>
        <extracomment>%2 and %4 are proportions such as 2.35 and 1.41 (long side : short side), %3 the sheet&apos;s size as given.</extracomment>
        <translation>%1: atrastā taisnstūra malu attiecība ir aptuveni %2 : 1, nevis %3 (%4 : 1); norādiet lapas izmēru ar --sheet vai tās četrus stūrus aptuveni ar --corners x,y;x,y;x,y;x,y</translation>
    </message>
    <message>
        <source>%1: no reference sheet found (a white rectangle with four straight, clear edges); give its four corners roughly with --corners x,y;x,y;x,y;x,y</source>
        <translation>%1: atskaites lapa nav atrasta (balts taisnstūris ar četrām taisnām, skaidrām malām); norādiet tās četrus stūrus aptuveni ar --corners x,y;x,y;x,y;x,y</translation>
    </message>
    <message>
        <source>%1: no pattern piece found beside the sheet; nothing was written (the sheet was found)</source>
        <translation>%1: blakus lapai nav atrasta neviena piegrieztnes detaļa; nekas netika ierakstīts (lapa tika atrasta)</translation>
    </message>
    <message>
        <source>%1: no grain line written for pieces without a grainline: %2</source>
        <translation>%1: detaļām bez diega virziena diega virziena līnija netika ierakstīta: %2</translation>
    </message>
</context>
<context>
    <name>kontur::print</name>
    <message>
        <source>Print at 100 % (actual size, not “fit to page”). The grey square must measure 10 cm each way.</source>
        <translation>Drukājiet 100 % mērogā (faktiskajā izmērā, nevis „ietilpināt lapā“). Pelēkajam kvadrātam katrā virzienā jābūt 10 cm.</translation>
    </message>
    <message>
        <source>landscape</source>
        <extracomment>Page orientation, inserted after the paper name in the sentence above (A4 landscape).</extracomment>
        <translation>ainavas orientācija</translation>
    </message>
    <message>
        <source>portrait</source>
        <translation>portreta orientācija</translation>
    </message>
    <message>
        <source>Cut each page along the grey line at its left and top, lay it over its neighbours up to their dashed lines, match the circles and tape.</source>
        <translation>Katrai lapai nogrieziet kreiso un augšējo malu pa pelēko līniju, uzlieciet to uz kaimiņlapām līdz to raustītajām līnijām, savietojiet aplīšus un salīmējiet.</translation>
    </message>
    <message>
        <source>The drawing is in px: printed at 96 px per inch.</source>
        <translation>Zīmējums ir pikseļos (px): drukāts ar 96 px collā.</translation>
    </message>
    <message>
        <source>10 cm</source>
        <translation>10 cm</translation>
    </message>
    <message>
        <source>4 in</source>
        <translation>4 collas</translation>
    </message>
    <message>
        <source>Pages after this one: %1 (rows × columns: %2 × %3), %4 %5, overlap %6 mm.</source>
        <extracomment>%1 is the number of pages, %2 × %3 their rows and columns, %4 the paper (A4 or Letter), %5 the orientation (“portrait” or “landscape”, the next messages), %6 a number of millimetres.</extracomment>
        <translation>Nākamās lapas: %1 (rindas × kolonnas: %2 × %3), %4, %5, pārklāšanās %6 mm.</translation>
    </message>
    <message>
        <source>Place on fold</source>
        <extracomment>Printed along a pattern piece&apos;s fold line: the piece is laid with this edge on the fabric&apos;s fold.</extracomment>
        <translation>Likt uz locījuma</translation>
    </message>
    <message>
        <source>Size %1</source>
        <extracomment>A pattern piece&apos;s size on the printed pattern (a garment size such as 38 or M).</extracomment>
        <translation>Izmērs %1</translation>
    </message>
    <message numerus="yes">
        <source>Cut %n on fold</source>
        <extracomment>How many pieces to cut, printed on the pattern piece; the piece lies on the fabric&apos;s fold.</extracomment>
        <translation>
            <numerusform>Piegriezt %n uz locījuma</numerusform>
            <numerusform>Piegriezt %n uz locījuma</numerusform>
            <numerusform>Piegriezt %n uz locījuma</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Cut %n</source>
        <extracomment>How many pieces to cut, printed on the pattern piece (&quot;Cut 2&quot;).</extracomment>
        <translation>
            <numerusform>Piegriezt %n</numerusform>
            <numerusform>Piegriezt %n</numerusform>
            <numerusform>Piegriezt %n</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 in</source>
        <extracomment>A seam&apos;s allowance width printed beside it on the pattern, in inches.</extracomment>
        <translation>%1 collas</translation>
    </message>
    <message>
        <source>%1 cm</source>
        <extracomment>A seam&apos;s allowance width printed beside it on the pattern, in centimetres (&quot;3 cm&quot;).</extracomment>
        <translation>%1 cm</translation>
    </message>
</context>
<context>
    <name>messages</name>
    <message>
        <source>Do you want to reset everything? All curves will be removed.</source>
        <translation>Vai vēlaties visu notīrīt? Visas līknes tiks noņemtas.</translation>
    </message>
    <message>
        <source>“%1” is locked: unlock it to change it.</source>
        <translation>„%1“ ir bloķēta: atbloķējiet to, lai mainītu.</translation>
    </message>
    <message>
        <source>Could not read “%1”: %2</source>
        <translation>Nevarēja nolasīt failu „%1“: %2</translation>
    </message>
    <message numerus="yes">
        <source>%n curve(s) read from “%1”.</source>
        <translation>
            <numerusform>No faila „%1“ nolasīta %n līkne.</numerusform>
            <numerusform>No faila „%1“ nolasītas %n līknes.</numerusform>
            <numerusform>No faila „%1“ nolasīts %n līkņu.</numerusform>
        </translation>
    </message>
    <message>
        <source>Saved “%1”.</source>
        <translation>Fails „%1“ saglabāts.</translation>
    </message>
    <message>
        <source>This knot lies on the first knot of the closed curve, which joins them already. Nothing was changed.</source>
        <translation>Šis mezgla punkts sakrīt ar slēgtās līknes pirmo mezgla punktu, un līkne tos jau savieno. Nekas netika mainīts.</translation>
    </message>
    <message>
        <source>This seam allowance follows its curve: change the curve or the allowance&apos;s settings, or detach the allowance to edit it.</source>
        <translation>Šī šuves pielaide seko savai līknei: mainiet līkni vai pielaides iestatījumus vai atsaistiet pielaidi, lai to labotu.</translation>
    </message>
    <message>
        <source>No seam allowance of this width fits the curve on that side.</source>
        <translation>Šāda platuma šuves pielaide līknei šajā pusē neietilpst.</translation>
    </message>
    <message>
        <source>This width is more than %1 times the size of the curve: no seam allowance is made of it. Nothing was changed.</source>
        <translation>Šis platums ir vairāk nekā %1 reizes lielāks par līknes izmēru: šādu šuves pielaidi neveido. Nekas netika mainīts.</translation>
    </message>
    <message>
        <source>This seam allowance would need too many pieces at this size. Nothing was changed.</source>
        <translation>Šai šuves pielaidei šādā izmērā būtu vajadzīgs pārāk daudz segmentu. Nekas netika mainīts.</translation>
    </message>
    <message>
        <source>The seam allowance “%1” keeps the shape it was saved with: its width %2 gives no allowance of its curve.</source>
        <translation>Šuves pielaide „%1“ paliek tādā formā, kādā tā tika saglabāta: ar platumu %2 tās līknei pielaidi izveidot nevar.</translation>
    </message>
    <message numerus="yes">
        <source>The autosave setting “%1” cannot be used: a recovery copy is saved every %n second(s).</source>
        <translation>
            <numerusform>Automātiskās saglabāšanas iestatījumu „%1“ nevar izmantot: atkopšanas kopija tiek saglabāta ik pēc %n sekundes.</numerusform>
            <numerusform>Automātiskās saglabāšanas iestatījumu „%1“ nevar izmantot: atkopšanas kopija tiek saglabāta ik pēc %n sekundēm.</numerusform>
            <numerusform>Automātiskās saglabāšanas iestatījumu „%1“ nevar izmantot: atkopšanas kopija tiek saglabāta ik pēc %n sekundēm.</numerusform>
        </translation>
    </message>
    <message>
        <source>The background image “%1” is missing or cannot be read. The curves are shown without it.</source>
        <translation>Fona attēla „%1“ nav vai to nevar nolasīt. Līknes tiek rādītas bez tā.</translation>
    </message>
    <message>
        <source>The picture “%1” could not be loaded: the file is missing or is not a picture Kontur can read.</source>
        <extracomment>%1 is a file name. The background picture could not be loaded.</extracomment>
        <translation>Attēlu „%1“ neizdevās ielādēt: fails nav atrodams vai nav attēls, ko Kontur var nolasīt.</translation>
    </message>
    <message>
        <source>The .txt file is not in the expected format: one “x y” pair per line.</source>
        <translation>.txt fails nav gaidītajā formātā: katrā rindā jābūt vienam pārim „x y“.</translation>
    </message>
    <message>
        <source>Could not append to “%1”: %2</source>
        <extracomment>%1 is a file name, %2 the reason (from the system). The curve&apos;s points are appended to a .txt file.</extracomment>
        <translation>Neizdevās papildināt failu „%1“: %2</translation>
    </message>
    <message>
        <source>The control points of curves of the kind “%1” cannot be moved: move the knots.</source>
        <extracomment>%1 is the name of a curve kind, as in the kind menu (&quot;Natural spline&quot;, &quot;Composite curve&quot;).</extracomment>
        <translation>Veida „%1“ līknēm kontrolpunktus pārvietot nevar: pārvietojiet mezgla punktus.</translation>
    </message>
    <message>
        <source>The control points of a composite curve cannot be moved by keyboard: drag them.</source>
        <translation>Saliktas līknes kontrolpunktus ar tastatūru pārvietot nevar: velciet tos.</translation>
    </message>
    <message>
        <source>Curves of the kind “%1” do not use a parameterization.</source>
        <extracomment>%1 is the name of a curve kind, as in the kind menu (&quot;Bézier curve&quot;, &quot;Natural spline&quot;).</extracomment>
        <translation>Veida „%1“ līknēm parametrizāciju neizmanto.</translation>
    </message>
    <message>
        <source>Too many points: a curve of this kind can have at most %1.</source>
        <extracomment>%1 is the largest number of points a curve of this kind can have (for example 1 000).</extracomment>
        <translation>Pārāk daudz punktu: šā veida līknei lielākais punktu skaits ir %1.</translation>
    </message>
    <message>
        <source>A curve of the kind “%1” needs at least %2 points.</source>
        <extracomment>%1 is the name of a curve kind, as in the kind menu (&quot;Bézier curve&quot;); %2 is a small number (2 to 4).</extracomment>
        <translation>Veida „%1“ līknei vajag vismaz %2 punktus.</translation>
    </message>
    <message>
        <source>Some values are missing or are not numbers: fill in every field with a number.</source>
        <translation>Dažu vērtību trūkst vai tās nav skaitļi: ierakstiet skaitli katrā laukā.</translation>
    </message>
    <message>
        <source>The knots of this curve (kind “%1”) do not define a curve: they need at least 4 different positions.</source>
        <extracomment>%1 is the name of a curve kind, as in the kind menu (&quot;Least-squares cubic&quot;).</extracomment>
        <translation>Šīs līknes (veids „%1“) mezgla punkti nenosaka līkni: vajadzīgas vismaz 4 dažādas vietas.</translation>
    </message>
    <message>
        <source>Too large: the coordinates would exceed the largest number Kontur can hold (about %1). Nothing was changed.</source>
        <translation>Pārāk liela vērtība: koordinātas pārsniegtu lielāko skaitli, ko Kontur var glabāt (aptuveni %1). Nekas netika mainīts.</translation>
    </message>
    <message>
        <source>This is not possible for curves of the kind “%1”.</source>
        <extracomment>%1 is the name of a curve kind, as in the kind menu (&quot;Bézier curve&quot;, &quot;Global B-spline&quot;).</extracomment>
        <translation>Veida „%1“ līknēm tas nav iespējams.</translation>
    </message>
    <message>
        <source>A seam allowance is still being computed: wait for it or cancel it first.</source>
        <translation>Šuves pielaide vēl tiek aprēķināta: pagaidiet vai vispirms atceliet to.</translation>
    </message>
    <message>
        <source>The seam allowance was cancelled. Nothing was changed.</source>
        <translation>Šuves pielaide tika atcelta. Nekas netika mainīts.</translation>
    </message>
    <message>
        <source>The curve changed while its seam allowance was computed. Nothing was changed; add or apply it again.</source>
        <translation>Līkne mainījās, kamēr tika aprēķināta tās šuves pielaide. Nekas netika mainīts; pievienojiet vai lietojiet to vēlreiz.</translation>
    </message>
    <message numerus="yes">
        <source>%n text(s)</source>
        <translation>
            <numerusform>%n teksts</numerusform>
            <numerusform>%n teksti</numerusform>
            <numerusform>%n tekstu</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n dimension(s)</source>
        <translation>
            <numerusform>%n izmērs</numerusform>
            <numerusform>%n izmēri</numerusform>
            <numerusform>%n izmēru</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n 3D object(s)</source>
        <translation>
            <numerusform>%n 3D objekts</numerusform>
            <numerusform>%n 3D objekti</numerusform>
            <numerusform>%n 3D objektu</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n image(s)</source>
        <translation>
            <numerusform>%n attēls</numerusform>
            <numerusform>%n attēli</numerusform>
            <numerusform>%n attēlu</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n spline(s) given only by fit points or weights</source>
        <translation>
            <numerusform>%n splains, dots tikai ar pieskaņošanas punktiem vai svariem</numerusform>
            <numerusform>%n splaini, doti tikai ar pieskaņošanas punktiem vai svariem</numerusform>
            <numerusform>%n splainu, dotu tikai ar pieskaņošanas punktiem vai svariem</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n other object(s)</source>
        <translation>
            <numerusform>%n cits objekts</numerusform>
            <numerusform>%n citi objekti</numerusform>
            <numerusform>%n citu objektu</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n curve(s) read from “%1”; not drawn: %2.</source>
        <translation>
            <numerusform>No faila „%1“ nolasīta %n līkne; nav uzzīmēts: %2.</numerusform>
            <numerusform>No faila „%1“ nolasītas %n līknes; nav uzzīmēts: %2.</numerusform>
            <numerusform>No faila „%1“ nolasīts %n līkņu; nav uzzīmēts: %2.</numerusform>
        </translation>
    </message>
    <message>
        <source>Could not write “%1”: %2 The file was left as it was.</source>
        <translation>Nevarēja ierakstīt failā „%1“: %2 Fails netika mainīts.</translation>
    </message>
    <message numerus="yes">
        <source>%n curve(s) read from “%1”, which does not say its units: read in %2, as chosen for such files.</source>
        <extracomment>%1 is a file name, %2 a unit (mm, cm, in or px) the user chose once for DXF files without units.</extracomment>
        <translation>
            <numerusform>No faila „%1“, kurā nav norādītas mērvienības, nolasīta %n līkne: mērvienības %2, kā izvēlēts šādiem failiem.</numerusform>
            <numerusform>No faila „%1“, kurā nav norādītas mērvienības, nolasītas %n līknes: mērvienības %2, kā izvēlēts šādiem failiem.</numerusform>
            <numerusform>No faila „%1“, kurā nav norādītas mērvienības, nolasīts %n līkņu: mērvienības %2, kā izvēlēts šādiem failiem.</numerusform>
        </translation>
    </message>
    <message>
        <source>Not drawn: %1.</source>
        <extracomment>Appended to the message that curves were read from a file; %1 lists what was not drawn.</extracomment>
        <translation>Nav uzzīmēts: %1.</translation>
    </message>
    <message>
        <source>DXF files that do not say their units are read in %1 from the next import on.</source>
        <extracomment>%1 is a unit (mm, cm, in or px).</extracomment>
        <translation>DXF faili, kuros nav norādītas mērvienības, no nākamās importēšanas tiek lasīti mērvienībās %1.</translation>
    </message>
    <message>
        <source>Nothing was exported: pattern software takes each piece as a closed curve, and this document has no visible closed curve. Close the outline of each piece first.</source>
        <extracomment>AAMA (ASTM D6673) is the DXF that garment pattern software reads; a piece is a garment pattern piece.</extracomment>
        <translation>Nekas netika eksportēts: piegrieztņu programmas katru detaļu pieņem kā noslēgtu līkni, bet šajā dokumentā nav nevienas redzamas noslēgtas līknes. Vispirms noslēdziet katras detaļas kontūru.</translation>
    </message>
    <message>
        <source>Seam allowance of %2 added to “%1”. To change it, select it and choose Seam allowance again.</source>
        <extracomment>%1 is the curve&apos;s name, %2 the width with its unit (10.00 mm).</extracomment>
        <translation>Līknei „%1“ pievienota šuves pielaide %2. Lai to mainītu, atlasiet to un vēlreiz izvēlieties „Šuves pielaide“.</translation>
    </message>
    <message numerus="yes">
        <source>“%1” traced with %n knot(s). For the next piece, choose Trace outline again.</source>
        <extracomment>%1 is the new curve&apos;s name; Trace outline is the command in the Trace menu.</extracomment>
        <translation>
            <numerusform>Līkne „%1“ pārzīmēta ar %n mezgla punktu. Nākamajai detaļai vēlreiz izvēlieties „Pārzīmēt kontūru“.</numerusform>
            <numerusform>Līkne „%1“ pārzīmēta ar %n mezgla punktiem. Nākamajai detaļai vēlreiz izvēlieties „Pārzīmēt kontūru“.</numerusform>
            <numerusform>Līkne „%1“ pārzīmēta ar %n mezgla punktiem. Nākamajai detaļai vēlreiz izvēlieties „Pārzīmēt kontūru“.</numerusform>
        </translation>
    </message>
    <message>
        <source>the grainline</source>
        <extracomment>One of the marks found on a traced pattern piece, listed after the curve&apos;s name.</extracomment>
        <translation>diega virziens</translation>
    </message>
    <message>
        <source>the fold line</source>
        <extracomment>One of the marks found on a traced pattern piece: the edge laid on the fabric&apos;s fold.</extracomment>
        <translation>locījuma līnija</translation>
    </message>
    <message numerus="yes">
        <source>%n notch(es)</source>
        <extracomment>One of the marks found on a traced pattern piece (V or slit cuts in its edge).</extracomment>
        <translation>
            <numerusform>%n iegriezums</numerusform>
            <numerusform>%n iegriezumi</numerusform>
            <numerusform>%n iegriezumu</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n drill hole(s)</source>
        <extracomment>One of the marks found on a traced pattern piece.</extracomment>
        <translation>
            <numerusform>%n urbuma atzīme</numerusform>
            <numerusform>%n urbuma atzīmes</numerusform>
            <numerusform>%n urbuma atzīmju</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>“%1” traced with %n knot(s) as a pattern piece with %2. Check them under Pattern piece; for the next piece, choose Trace outline again.</source>
        <extracomment>%1 is the new curve&apos;s name, %2 the marks found on it (&quot;the grainline, 3 notches, 1 drill hole&quot;); Pattern piece is the command that opens the piece bar; Trace outline the command in the Trace menu.</extracomment>
        <translation>
            <numerusform>Līkne „%1“ pārzīmēta ar %n mezgla punktu kā piegrieztnes detaļa; atrastās atzīmes: %2. Pārbaudiet tās sadaļā „Piegrieztnes detaļa“; nākamajai detaļai vēlreiz izvēlieties „Pārzīmēt kontūru“.</numerusform>
            <numerusform>Līkne „%1“ pārzīmēta ar %n mezgla punktiem kā piegrieztnes detaļa; atrastās atzīmes: %2. Pārbaudiet tās sadaļā „Piegrieztnes detaļa“; nākamajai detaļai vēlreiz izvēlieties „Pārzīmēt kontūru“.</numerusform>
            <numerusform>Līkne „%1“ pārzīmēta ar %n mezgla punktiem kā piegrieztnes detaļa; atrastās atzīmes: %2. Pārbaudiet tās sadaļā „Piegrieztnes detaļa“; nākamajai detaļai vēlreiz izvēlieties „Pārzīmēt kontūru“.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>“%1” was written, but %n piece(s) without a grainline have no grain line in it: %2. Marker making cannot lay them on grain; draw each piece&apos;s grainline.</source>
        <extracomment>%1 is the file, %2 the pieces&apos; names; the grainline is the pattern piece&apos;s straight-of-grain line.</extracomment>
        <translation>
            <numerusform>„%1“ ierakstīts, bet %n detaļai bez diega virziena tajā nav diega virziena līnijas: %2. Izkārtojumā to nevar novietot pa diega virzienu; uzzīmējiet katrai detaļai diega virzienu.</numerusform>
            <numerusform>„%1“ ierakstīts, bet %n detaļām bez diega virziena tajā nav diega virziena līnijas: %2. Izkārtojumā tās nevar novietot pa diega virzienu; uzzīmējiet katrai detaļai diega virzienu.</numerusform>
            <numerusform>„%1“ ierakstīts, bet %n detaļām bez diega virziena tajā nav diega virziena līnijas: %2. Izkārtojumā tās nevar novietot pa diega virzienu; uzzīmējiet katrai detaļai diega virzienu.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>units</name>
    <message>
        <source>%1 mm</source>
        <extracomment>A length in millimetres; %1 is a decimal number (12,35).</extracomment>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>%1 cm</source>
        <extracomment>A length in centimetres; %1 is a decimal number (1,235).</extracomment>
        <translation>%1 cm</translation>
    </message>
    <message>
        <source>%1 in</source>
        <extracomment>A length in inches; %1 is a decimal number with three decimals (0,500), so the unit takes the form it has after a fraction.</extracomment>
        <translation>%1 collas</translation>
    </message>
    <message>
        <source>%1 px</source>
        <extracomment>A length in pixels of the picture; %1 is a decimal number (30,0).</extracomment>
        <translation>%1 px</translation>
    </message>
    <message>
        <source>%1 pt</source>
        <extracomment>A length in typographic points (1/72 inch); %1 is a decimal number (2,3).</extracomment>
        <translation>%1 pt</translation>
    </message>
    <message>
        <source>mm</source>
        <extracomment>The unit millimetres, alone: in a list of units and in headings such as &quot;X, mm&quot;.</extracomment>
        <translation>mm</translation>
    </message>
    <message>
        <source>cm</source>
        <extracomment>The unit centimetres, alone: in a list of units and in headings such as &quot;X, cm&quot;.</extracomment>
        <translation>cm</translation>
    </message>
    <message>
        <source>in</source>
        <extracomment>The unit inches, alone: in a list of units (mm, cm, in) and in headings such as &quot;X, in&quot;.</extracomment>
        <translation>collas</translation>
    </message>
    <message>
        <source>px</source>
        <extracomment>The unit pixels (of the picture), alone: in headings such as &quot;X, px&quot;.</extracomment>
        <translation>px</translation>
    </message>
    <message>
        <source>pt</source>
        <extracomment>The unit typographic points (1/72 inch), alone: in headings such as &quot;X, pt&quot;.</extracomment>
        <translation>pt</translation>
    </message>
</context>
</TS>
