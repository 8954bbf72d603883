<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="sk">
<context>
    <name>AppActions</name>
    <message>
        <source>File</source>
        <extracomment>Menu title (noun): the file commands.</extracomment>
        <translation>Súbor</translation>
    </message>
    <message>
        <source>New, open, save, import and export</source>
        <translation>Nový dokument, otvorenie, uloženie, import a export</translation>
    </message>
    <message>
        <source>Open %1</source>
        <translation>Otvoriť %1</translation>
    </message>
    <message>
        <source>Export PNG (view size)…</source>
        <translation>Exportovať PNG (veľkosť zobrazenia)…</translation>
    </message>
    <message>
        <source>Export PNG (2× view size)…</source>
        <translation>Exportovať PNG (2× veľkosť zobrazenia)…</translation>
    </message>
    <message>
        <source>Export PNG (4× view size)…</source>
        <translation>Exportovať PNG (4× veľkosť zobrazenia)…</translation>
    </message>
    <message>
        <source>Export PNG of the whole document (2×)…</source>
        <translation>Exportovať PNG celého dokumentu (2×)…</translation>
    </message>
    <message>
        <source>Quit</source>
        <translation>Ukončiť</translation>
    </message>
    <message>
        <source>New Bézier</source>
        <extracomment>Tool-bar button, short for “New Bézier curve”: starts placing the control points of a new Bézier curve.</extracomment>
        <translation>Nová Bézierova krivka</translation>
    </message>
    <message>
        <source>Place 4 control points to make a cubic Bézier curve (B)</source>
        <translation>Umiestnite 4 kontrolné body a vytvorte kubickú Bézierovu krivku (B)</translation>
    </message>
    <message>
        <source>New curve</source>
        <translation>Nová krivka</translation>
    </message>
    <message>
        <source>Choose the kind of curve to place</source>
        <translation>Vyberte druh krivky, ktorú chcete umiestniť</translation>
    </message>
    <message>
        <source>Done</source>
        <extracomment>Button: finishes the curve being placed (keeps the points placed so far).</extracomment>
        <translation>Hotovo</translation>
    </message>
    <message>
        <source>Finish the curve with the points placed so far (Enter)</source>
        <translation>Dokončiť krivku s doteraz umiestnenými bodmi (Enter)</translation>
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
        <source>Constrained handles</source>
        <translation>Obmedzené úchyty</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Späť</translation>
    </message>
    <message>
        <source>Undo (Ctrl+Z)</source>
        <translation>Späť (Ctrl+Z)</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Znova</translation>
    </message>
    <message>
        <source>Redo (Ctrl+Shift+Z)</source>
        <translation>Znova (Ctrl+Shift+Z)</translation>
    </message>
    <message>
        <source>Reset all</source>
        <translation>Vymazať všetko</translation>
    </message>
    <message>
        <source>Remove every curve and the background picture</source>
        <translation>Odstrániť všetky krivky a obrázok na pozadí</translation>
    </message>
    <message>
        <source>Teaching</source>
        <extracomment>Menu title (noun): the teaching views (de Casteljau, degree elevation, basis functions…).</extracomment>
        <translation>Výučba</translation>
    </message>
    <message>
        <source>Views that show how curves are built</source>
        <translation>Zobrazenia, ktoré ukazujú, ako vznikajú krivky</translation>
    </message>
    <message>
        <source>de Casteljau construction</source>
        <translation>de Casteljauova konštrukcia</translation>
    </message>
    <message>
        <source>Degree elevation</source>
        <translation>Zvýšenie stupňa</translation>
    </message>
    <message>
        <source>Compare curve kinds</source>
        <translation>Porovnať druhy kriviek</translation>
    </message>
    <message>
        <source>Curvature comb and continuity</source>
        <translation>Hrebeň krivosti a spojitosť</translation>
    </message>
    <message>
        <source>Basis functions</source>
        <translation>Bázové funkcie</translation>
    </message>
    <message>
        <source>Function spline y(x)…</source>
        <translation>Funkčný splajn y(x)…</translation>
    </message>
    <message>
        <source>Runge phenomenon: comparison…</source>
        <translation>Rungeho jav: porovnanie…</translation>
    </message>
    <message>
        <source>Cubic segments with guide vectors…</source>
        <translation>Kubické segmenty so smerovými vektormi…</translation>
    </message>
    <message>
        <source>Presentation mode (F5)</source>
        <translation>Prezentačný režim (F5)</translation>
    </message>
    <message>
        <source>Trace</source>
        <extracomment>Menu title: the tools for tracing a pattern from a photo; a title, not an order.</extracomment>
        <translation>Obkresliť</translation>
    </message>
    <message>
        <source>Trace a pattern: freehand, calibrate, measure, compare</source>
        <translation>Obkresliť strih: voľnou rukou, kalibrovať, merať, porovnať</translation>
    </message>
    <message>
        <source>Freehand (T)</source>
        <translation>Voľnou rukou (T)</translation>
    </message>
    <message>
        <source>Calibrate background (K)</source>
        <translation>Kalibrovať pozadie (K)</translation>
    </message>
    <message>
        <source>Measure distance (M)</source>
        <translation>Merať vzdialenosť (M)</translation>
    </message>
    <message>
        <source>Seam length between knots (L)</source>
        <translation>Dĺžka švu medzi uzlami (L)</translation>
    </message>
    <message>
        <source>Move background (O)</source>
        <translation>Posúvať pozadie (O)</translation>
    </message>
    <message>
        <source>Snap to knots, grid and marks (S)</source>
        <translation>Prichytiť k uzlom, mriežke a značkám (S)</translation>
    </message>
    <message>
        <source>Lock background</source>
        <translation>Zamknúť pozadie</translation>
    </message>
    <message>
        <source>Zoom in</source>
        <translation>Priblížiť</translation>
    </message>
    <message>
        <source>Zoom in (+)</source>
        <translation>Priblížiť (+)</translation>
    </message>
    <message>
        <source>Zoom out</source>
        <translation>Oddialiť</translation>
    </message>
    <message>
        <source>Zoom out (−)</source>
        <translation>Oddialiť (−)</translation>
    </message>
    <message>
        <source>Fit to view</source>
        <extracomment>Command: zoom so that all curves fit in the window.</extracomment>
        <translation>Prispôsobiť oknu</translation>
    </message>
    <message>
        <source>Show all curves (F)</source>
        <translation>Zobraziť všetky krivky (F)</translation>
    </message>
    <message>
        <source>Grid</source>
        <extracomment>Toggle (noun): show or hide the grid on the canvas.</extracomment>
        <translation>Mriežka</translation>
    </message>
    <message>
        <source>Show or hide the grid and the axes (G)</source>
        <translation>Zobraziť alebo skryť mriežku a osi (G)</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Jazyk</translation>
    </message>
    <message>
        <source>Side panel</source>
        <translation>Bočný panel</translation>
    </message>
    <message>
        <source>Show or hide the side panel: the curves, their points and settings</source>
        <translation>Zobraziť alebo skryť bočný panel: krivky, ich body a nastavenia</translation>
    </message>
    <message>
        <source>Seam allowance…</source>
        <translation>Prídavok na šev…</translation>
    </message>
    <message>
        <source>Calibrate perspective (Shift+K)</source>
        <translation>Kalibrovať perspektívu (Shift+K)</translation>
    </message>
    <message>
        <source>Make line</source>
        <translation>Narovnať segment</translation>
    </message>
    <message>
        <source>Make the selected segment a straight line; its knots become corners (Shift+L)</source>
        <translation>Zmeniť vybraný segment na úsečku; jeho uzly sa stanú ostrými (Shift+L)</translation>
    </message>
    <message>
        <source>Delete knot</source>
        <translation>Odstrániť uzol</translation>
    </message>
    <message>
        <source>Delete the selected knot; its two segments become one</source>
        <translation>Odstrániť vybraný uzol; jeho dva segmenty sa spoja do jedného</translation>
    </message>
    <message>
        <source>Smooth knot</source>
        <translation>Hladký uzol</translation>
    </message>
    <message>
        <source>The handles of the selected knot stay on one line (Shift+S)</source>
        <translation>Úchyty vybraného uzla zostávajú na jednej priamke (Shift+S)</translation>
    </message>
    <message>
        <source>Symmetric knot</source>
        <translation>Symetrický uzol</translation>
    </message>
    <message>
        <source>The handles of the selected knot mirror each other (Shift+Y)</source>
        <translation>Úchyty vybraného uzla sú navzájom zrkadlovo súmerné (Shift+Y)</translation>
    </message>
    <message>
        <source>Corner knot</source>
        <translation>Ostrý uzol</translation>
    </message>
    <message>
        <source>The handles of the selected knot move independently (Shift+C)</source>
        <translation>Úchyty vybraného uzla sa pohybujú nezávisle (Shift+C)</translation>
    </message>
    <message>
        <source>Close curve</source>
        <translation>Uzavrieť krivku</translation>
    </message>
    <message>
        <source>Join the curve&apos;s last knot to its first; ends that meet become one knot (Shift+O)</source>
        <translation>Spojiť posledný uzol krivky s prvým; konce, ktoré sa stretávajú, sa stanú jedným uzlom (Shift+O)</translation>
    </message>
    <message>
        <source>Join curves</source>
        <translation>Spojiť krivky</translation>
    </message>
    <message>
        <source>Join the selected curve with the curve whose end is nearest to one of its ends (Shift+J)</source>
        <translation>Spojiť vybranú krivku s krivkou, ktorej koniec je najbližšie k jednému z jej koncov (Shift+J)</translation>
    </message>
    <message>
        <source>Simplify curve…</source>
        <translation>Zjednodušiť krivku…</translation>
    </message>
    <message>
        <source>Fewer knots within a tolerance you type</source>
        <translation>Menej uzlov v rámci zadanej tolerancie</translation>
    </message>
    <message>
        <source>Trace outline</source>
        <translation>Obkresliť obrys</translation>
    </message>
    <message>
        <source>The handles of composite curves keep their direction and change only their length (or drag with the right button or Shift)</source>
        <translation>Úchyty zložených kriviek si zachovajú smer a menia len dĺžku (alebo ťahajte pravým tlačidlom či s klávesom Shift)</translation>
    </message>
    <message>
        <source>Deviation from a reference curve (D)</source>
        <translation>Odchýlka od referenčnej krivky (D)</translation>
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
        <translation>Priblíženie %1</translation>
    </message>
    <message>
        <source>More</source>
        <extracomment>Tool-bar button that opens a menu with the commands that do not fit on the bar.</extracomment>
        <translation>Viac</translation>
    </message>
    <message>
        <source>More commands</source>
        <translation>Ďalšie príkazy</translation>
    </message>
</context>
<context>
    <name>BasisPlot</name>
    <message numerus="yes">
        <source>Too many basis functions to draw (%n).</source>
        <translation>
            <numerusform>Príliš veľa bázových funkcií na vykreslenie (%n).</numerusform>
            <numerusform>Príliš veľa bázových funkcií na vykreslenie (%n).</numerusform>
            <numerusform>Príliš veľa bázových funkcií na vykreslenie (%n).</numerusform>
        </translation>
    </message>
    <message>
        <source>Bernstein polynomials of degree %1</source>
        <translation>Bernsteinove polynómy stupňa %1</translation>
    </message>
    <message>
        <source>B-spline basis functions N(i,k), order k = %1</source>
        <translation>Bázové funkcie B-splajnu N(i,k), rád k = %1</translation>
    </message>
    <message>
        <source>Bell functions Bs of degree %1</source>
        <extracomment>Title: the bell-shaped B-spline basis functions Bs (one bell per knot) of degree %1 (a number).</extracomment>
        <translation>Zvonové funkcie Bs stupňa %1</translation>
    </message>
    <message>
        <source>Hermite basis functions on one segment</source>
        <translation>Hermitove bázové funkcie na jednom segmente</translation>
    </message>
    <message>
        <source>Knot vector: %1</source>
        <translation>Uzlový vektor: %1</translation>
    </message>
    <message>
        <source> (sum %1)</source>
        <translation> (súčet %1)</translation>
    </message>
    <message numerus="yes">
        <source>Hermite basis functions on the curve&apos;s %n segment(s)</source>
        <translation>
            <numerusform>Hermitove bázové funkcie na %n segmente krivky</numerusform>
            <numerusform>Hermitove bázové funkcie na %n segmentoch krivky</numerusform>
            <numerusform>Hermitove bázové funkcie na %n segmentoch krivky</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>BasisPlotPanel</name>
    <message>
        <source>Collapse the basis functions</source>
        <translation>Zbaliť bázové funkcie</translation>
    </message>
    <message>
        <source>Expand the basis functions</source>
        <translation>Rozbaliť bázové funkcie</translation>
    </message>
    <message>
        <source>Of the selected curve</source>
        <extracomment>Choices of the basis functions plotted: the selected curve&apos;s own, or a family named with its basis.</extracomment>
        <translation>Vybranej krivky</translation>
    </message>
    <message>
        <source>B-spline</source>
        <translation>B-splajn</translation>
    </message>
    <message>
        <source>Bell functions</source>
        <translation>Zvonové funkcie</translation>
    </message>
    <message>
        <source>Basis functions</source>
        <translation>Bázové funkcie</translation>
    </message>
    <message>
        <source>Degree</source>
        <translation>Stupeň</translation>
    </message>
    <message>
        <source>Order</source>
        <extracomment>Label (noun): the order k of the B-spline basis functions (degree + 1), a number.</extracomment>
        <translation>Rád</translation>
    </message>
    <message>
        <source>Functions</source>
        <extracomment>Label (noun): how many basis functions are drawn (a number beside it).</extracomment>
        <translation>Funkcie</translation>
    </message>
    <message>
        <source>Number of basis functions</source>
        <translation>Počet bázových funkcií</translation>
    </message>
    <message>
        <source>Close the basis functions</source>
        <translation>Zavrieť bázové funkcie</translation>
    </message>
    <message>
        <source>Plot of the basis functions; the left and right arrow keys move t</source>
        <translation>Graf bázových funkcií; šípky doľava a doprava posúvajú t</translation>
    </message>
    <message>
        <source>Bernstein basis</source>
        <translation>Bernsteinova báza</translation>
    </message>
    <message>
        <source>Hermite basis</source>
        <translation>Hermitova báza</translation>
    </message>
    <message>
        <source>Make the basis functions smaller</source>
        <translation>Zmenšiť bázové funkcie</translation>
    </message>
    <message>
        <source>Enlarge the basis functions</source>
        <translation>Zväčšiť bázové funkcie</translation>
    </message>
</context>
<context>
    <name>BottomSheet</name>
    <message>
        <source>Panel size: tap to show more, drag to resize</source>
        <translation>Výška panela: ťuknutím zobrazíte viac, potiahnutím zmeníte výšku</translation>
    </message>
</context>
<context>
    <name>CanvasView</name>
    <message>
        <source>grid %1</source>
        <extracomment>%1 is the grid spacing in the document&apos;s units (a number).</extracomment>
        <translation>mriežka %1</translation>
    </message>
</context>
<context>
    <name>ConfirmDialog</name>
    <message>
        <source>Yes</source>
        <translation>Áno</translation>
    </message>
    <message>
        <source>No</source>
        <translation>Nie</translation>
    </message>
</context>
<context>
    <name>CoordinatesTable</name>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Reset</source>
        <extracomment>Button: throws away the values typed in the table; the curve stays as it was.</extracomment>
        <translation>Zahodiť zmeny</translation>
    </message>
    <message>
        <source>Add row</source>
        <translation>Pridať riadok</translation>
    </message>
    <message>
        <source>Delete row</source>
        <translation>Odstrániť riadok</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>Skopírovať</translation>
    </message>
</context>
<context>
    <name>FileActions</name>
    <message>
        <source>New</source>
        <extracomment>Command (verb/adjective): start a new, empty document.</extracomment>
        <translation>Nový</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Otvoriť…</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Uložiť</translation>
    </message>
    <message>
        <source>Save as…</source>
        <translation>Uložiť ako…</translation>
    </message>
    <message>
        <source>Export SVG…</source>
        <translation>Exportovať SVG…</translation>
    </message>
    <message>
        <source>Export the selected curve as CSV…</source>
        <translation>Exportovať vybranú krivku ako CSV…</translation>
    </message>
    <message>
        <source>Append the selected curve to a points file…</source>
        <translation>Pripojiť vybranú krivku na koniec súboru bodov…</translation>
    </message>
    <message>
        <source>Kontur documents (*.kontur)</source>
        <translation>Dokumenty Kontur (*.kontur)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Všetky súbory (*)</translation>
    </message>
    <message>
        <source>Open</source>
        <extracomment>Title of the file dialog that opens a document (verb: open a file).</extracomment>
        <translation>Otvoriť</translation>
    </message>
    <message>
        <source>Save as</source>
        <translation>Uložiť ako</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Importovať</translation>
    </message>
    <message>
        <source>Export SVG</source>
        <translation>Exportovať SVG</translation>
    </message>
    <message>
        <source>SVG images (*.svg)</source>
        <translation>Obrázky SVG (*.svg)</translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation>Exportovať CSV</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>Súbory CSV (*.csv)</translation>
    </message>
    <message>
        <source>Append to a points file</source>
        <translation>Pripojiť na koniec súboru bodov</translation>
    </message>
    <message>
        <source>Points files (*.txt)</source>
        <translation>Súbory bodov (*.txt)</translation>
    </message>
    <message>
        <source>Export PNG</source>
        <translation>Exportovať PNG</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>Obrázky PNG (*.png)</translation>
    </message>
    <message>
        <source>Load background image</source>
        <translation>Načítať obrázok na pozadí</translation>
    </message>
    <message>
        <source>Images (*.png *.jpg *.jpeg *.heic *.heif *.bmp *.gif *.webp)</source>
        <translation>Obrázky (*.png *.jpg *.jpeg *.heic *.heif *.bmp *.gif *.webp)</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Neuložené zmeny</translation>
    </message>
    <message>
        <source>“%1” has changes that are not saved. Save them first?</source>
        <translation>Dokument „%1“ má neuložené zmeny. Chcete ich najprv uložiť?</translation>
    </message>
    <message>
        <source>Don’t save</source>
        <translation>Neuložiť</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Zrušiť</translation>
    </message>
    <message>
        <source>Recover unsaved work</source>
        <translation>Obnoviť neuloženú prácu</translation>
    </message>
    <message>
        <source>Kontur was not closed properly last time. Recover the unsaved work?</source>
        <translation>Kontur sa minule neukončil správne. Chcete obnoviť neuloženú prácu?</translation>
    </message>
    <message>
        <source>Recover</source>
        <translation>Obnoviť</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Zahodiť</translation>
    </message>
    <message>
        <source>Print pattern…</source>
        <translation>Vytlačiť strih…</translation>
    </message>
    <message>
        <source>Print pattern to PDF</source>
        <translation>Vytlačiť strih do PDF</translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation>Súbory PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Kontur documents and printed patterns (%1)</source>
        <translation>Dokumenty Kontur a vytlačené strihy (%1)</translation>
    </message>
    <message>
        <source>Import points, CSV, SVG or DXF…</source>
        <translation>Importovať body, CSV, SVG alebo DXF…</translation>
    </message>
    <message>
        <source>Export DXF with splines…</source>
        <translation>Exportovať DXF so splajnmi…</translation>
    </message>
    <message>
        <source>The exact curves as DXF splines, in the document&apos;s units, for CAD and pattern software</source>
        <translation>Presné krivky ako splajny DXF v jednotkách dokumentu, pre CAD a programy na strihy</translation>
    </message>
    <message>
        <source>Export DXF with polylines…</source>
        <translation>Exportovať DXF s lomenými čiarami…</translation>
    </message>
    <message>
        <source>The curves as DXF polylines within 0.05 mm, for plotters and cutters without splines</source>
        <translation>Krivky ako lomené čiary DXF s presnosťou 0,05 mm, pre plotre a rezačky bez splajnov</translation>
    </message>
    <message>
        <source>Points, CSV, SVG and DXF files (%1)</source>
        <translation>Súbory bodov, CSV, SVG a DXF (%1)</translation>
    </message>
    <message>
        <source>Points, CSV, SVG, DXF, Kontur files and printed patterns (%1)</source>
        <translation>Súbory bodov, CSV, SVG, DXF, Kontur a vytlačené strihy (%1)</translation>
    </message>
    <message>
        <source>Export DXF</source>
        <translation>Exportovať DXF</translation>
    </message>
    <message>
        <source>DXF drawings (*.dxf)</source>
        <translation>Výkresy DXF (*.dxf)</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportovať</translation>
    </message>
    <message>
        <source>Append</source>
        <translation>Pripojiť</translation>
    </message>
    <message>
        <source>Export DXF for pattern software (AAMA)…</source>
        <extracomment>AAMA (ASTM D6673) is the DXF that garment pattern software and cutters exchange pieces in.</extracomment>
        <translation>Exportovať DXF pre programy na strihy (AAMA)…</translation>
    </message>
    <message>
        <source>Each closed curve as a pattern piece (ASTM D6673): its seam allowance as the cut line, the curve as the sew line, polylines within 0.05 mm</source>
        <translation>Každá uzavretá krivka ako diel strihu (ASTM D6673): jej prídavok na šev ako línia strihu, krivka ako línia šitia, lomené čiary s presnosťou 0,05 mm</translation>
    </message>
    <message>
        <source>Export DXF for pattern software</source>
        <translation>Exportovať DXF pre programy na strihy</translation>
    </message>
</context>
<context>
    <name>FileBrowserDialog</name>
    <message>
        <source>Save</source>
        <translation>Uložiť</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Otvoriť</translation>
    </message>
</context>
<context>
    <name>FileBrowserPage</name>
    <message>
        <source>Up one folder</source>
        <extracomment>File dialog: go to the folder that contains this one.</extracomment>
        <translation>O priečinok vyššie</translation>
    </message>
    <message>
        <source>Folder or file path</source>
        <extracomment>File dialog: the field that shows the folder&apos;s path and takes a typed one.</extracomment>
        <translation>Cesta k priečinku alebo súboru</translation>
    </message>
    <message>
        <source>Go</source>
        <extracomment>File dialog: go to the folder or file typed into the path field.</extracomment>
        <translation>Prejsť</translation>
    </message>
    <message>
        <source>There is no folder or file “%1”.</source>
        <translation>Priečinok ani súbor „%1“ neexistuje.</translation>
    </message>
    <message>
        <source>The folder “%1” cannot be read.</source>
        <translation>Priečinok „%1“ sa nedá prečítať.</translation>
    </message>
    <message>
        <source>Type a name for the file.</source>
        <translation>Zadajte názov súboru.</translation>
    </message>
    <message>
        <source>No folders and no matching files here.</source>
        <extracomment>File dialog: the folder shown has no subfolder and no file that the filter lets through.</extracomment>
        <translation>Nie sú tu žiadne priečinky ani zodpovedajúce súbory.</translation>
    </message>
    <message>
        <source>Files of type</source>
        <extracomment>File dialog: which kinds of files the list shows.</extracomment>
        <translation>Typ súborov</translation>
    </message>
    <message>
        <source>Name</source>
        <extracomment>File dialog: the name of the file to save.</extracomment>
        <translation>Názov</translation>
    </message>
    <message>
        <source>File name</source>
        <translation>Názov súboru</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Zrušiť</translation>
    </message>
    <message>
        <source>Replace the file?</source>
        <translation>Nahradiť súbor?</translation>
    </message>
    <message>
        <source>“%1” already exists. Replace it?</source>
        <translation>„%1“ už existuje. Nahradiť ho?</translation>
    </message>
    <message>
        <source>Replace</source>
        <translation>Nahradiť</translation>
    </message>
</context>
<context>
    <name>FirstRunHint</name>
    <message>
        <source>New curve</source>
        <translation>Nová krivka</translation>
    </message>
    <message>
        <source>Tap four points of a Bézier curve</source>
        <translation>Ťuknite na štyri body Bézierovej krivky</translation>
    </message>
    <message>
        <source>Open a file</source>
        <translation>Otvoriť súbor</translation>
    </message>
    <message>
        <source>A Kontur document</source>
        <translation>Dokument Kontur</translation>
    </message>
    <message>
        <source>Trace a picture</source>
        <translation>Obkresliť obrázok</translation>
    </message>
    <message>
        <source>Load a photo or scan and draw over it</source>
        <translation>Načítajte obrázok (fotografiu alebo sken) a kreslite po ňom</translation>
    </message>
</context>
<context>
    <name>FunctionSplinePlot</name>
    <message>
        <source>Change the function spline</source>
        <translation>Zmeniť funkčný splajn</translation>
    </message>
</context>
<context>
    <name>FunctionSplineView</name>
    <message>
        <source>Function spline y(x)</source>
        <translation>Funkčný splajn y(x)</translation>
    </message>
    <message>
        <source>Close</source>
        <extracomment>Button (verb): closes this teaching view and returns to the drawing.</extracomment>
        <translation>Zavrieť</translation>
    </message>
    <message>
        <source>Spline</source>
        <extracomment>Heading (noun): the kind of spline to draw.</extracomment>
        <translation>Splajn</translation>
    </message>
    <message>
        <source>Natural spline</source>
        <translation>Prirodzený splajn</translation>
    </message>
    <message>
        <source>Clamped spline (C-spline)</source>
        <translatorcomment>clamped splajn: the term of the Košice course (glossary); in prose a teacher says splajn s danými deriváciami na koncoch.</translatorcomment>
        <translation>Clamped splajn (C-splajn)</translation>
    </message>
    <message>
        <source>Hermite spline (H-spline)</source>
        <translation>Hermitov splajn (H-splajn)</translation>
    </message>
    <message>
        <source>Global B-spline</source>
        <translation>Globálny B-splajn</translation>
    </message>
    <message>
        <source>B-spline of bell functions</source>
        <translation>B-splajn zo zvonových funkcií</translation>
    </message>
    <message>
        <source>Control values</source>
        <translation>Riadiace hodnoty</translation>
    </message>
    <message>
        <source>Function values</source>
        <translation>Funkčné hodnoty</translation>
    </message>
    <message>
        <source>Regular (uniform) knots</source>
        <translation>Pravidelné (uniformné) uzly</translation>
    </message>
    <message>
        <source>Interval</source>
        <extracomment>Heading (noun): the interval [a, b] of evenly spaced knots; otherwise the knots x₀ … xₙ are typed one by one.</extracomment>
        <translation>Interval</translation>
    </message>
    <message>
        <source>Knots</source>
        <translation>Uzly</translation>
    </message>
    <message>
        <source>Derivatives (one per knot)</source>
        <translation>Derivácie (jedna v každom uzle)</translation>
    </message>
    <message>
        <source>Derivatives (first and last knot)</source>
        <translation>Derivácie (v prvom a poslednom uzle)</translation>
    </message>
    <message>
        <source>Derivatives</source>
        <extracomment>Screen-reader name of the field for the derivatives at the two ends (clamped spline).</extracomment>
        <translation>Derivácie</translation>
    </message>
    <message>
        <source>Draw</source>
        <extracomment>Button (verb): draws the spline from the values typed above.</extracomment>
        <translation>Nakresliť</translation>
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
        <source>Interpolating polynomial through the same points</source>
        <translation>Interpolačný polynóm cez tie isté body</translation>
    </message>
    <message>
        <source>Runge&apos;s example</source>
        <translation>Rungeho príklad</translation>
    </message>
    <message>
        <source>Points of Runge&apos;s example</source>
        <translation>Body Rungeho príkladu</translation>
    </message>
    <message>
        <source>Drag a green knot up or down, or a grey handle to change the derivative: its slope to the knot is the derivative.</source>
        <translation>Potiahnite zelený uzol nahor alebo nadol, alebo sivým úchytom zmeňte deriváciu: smernica spojnice úchytu s uzlom je derivácia.</translation>
    </message>
    <message>
        <source>Runge phenomenon: comparison</source>
        <translation>Rungeho jav: porovnanie</translation>
    </message>
    <message>
        <source>Solver</source>
        <translation>Riešenie sústavy</translation>
    </message>
    <message>
        <source>Classical: k − 2 unknowns</source>
        <translation>Klasické: k − 2 neznámych</translation>
    </message>
    <message>
        <source>Török: half-size system</source>
        <translation>Török: sústava polovičnej veľkosti</translation>
    </message>
    <message>
        <source>Add to document</source>
        <translation>Pridať do dokumentu</translation>
    </message>
    <message>
        <source>Added to the document as “%1”.</source>
        <translation>Pridané do dokumentu ako „%1“.</translation>
    </message>
    <message>
        <source>Add this spline to the drawing as a curve (undone in one step)</source>
        <translation>Pridať tento splajn do kresby ako krivku (dá sa vrátiť jedným krokom)</translation>
    </message>
    <message>
        <source>Course examples</source>
        <extracomment>Heading: buttons that load the course&apos;s worked examples.</extracomment>
        <translation>Príklady z kurzu</translation>
    </message>
    <message>
        <source>Török&apos;s example</source>
        <extracomment>Button: loads Török&apos;s example (values 3 2 −1 0,5, end slopes 0, his solver).</extracomment>
        <translation>Törökov príklad</translation>
    </message>
    <message>
        <source>Example 1.23</source>
        <extracomment>Button: loads the course&apos;s Example 1.23 (a global B-spline); keep the number.</extracomment>
        <translation>Príklad 1.23</translation>
    </message>
    <message>
        <source>Example 1.30</source>
        <extracomment>Button: loads the course&apos;s Example 1.30 (a Hermite spline); keep the number.</extracomment>
        <translation>Príklad 1.30</translation>
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
        <translation>Stlačte „Nová Bézierova krivka“ a ťuknutím zadajte 4 body svojej prvej krivky.</translation>
    </message>
    <message>
        <source>Drag a point to move it. Drag the canvas to pan; pinch or scroll to zoom.</source>
        <translation>Ťahaním bod posuniete. Ťahaním plátna posúvate pohľad; priblížite roztiahnutím dvoch prstov alebo kolieskom myši.</translation>
    </message>
    <message>
        <source>New curve: tap or click its points (%1 placed). Press Done to finish, Esc to cancel.</source>
        <translation>Nová krivka: ťuknite alebo kliknite na jej body (umiestnené: %1). Dokončite tlačidlom Hotovo, zrušte klávesom Esc.</translation>
    </message>
    <message>
        <source>New curve: tap or click point %1 of %2. Esc cancels.</source>
        <translation>Nová krivka: ťuknite alebo kliknite a umiestnite bod %1 z %2. Esc zruší.</translation>
    </message>
    <message>
        <source>Grainline: tap its other end.</source>
        <translation>Smer osnovy: ťuknite na jej druhý koniec.</translation>
    </message>
    <message>
        <source>Grainline: tap one end, then the other.</source>
        <translation>Smer osnovy: ťuknite na jeden koniec, potom na druhý.</translation>
    </message>
    <message>
        <source>On fold: tap the fold line&apos;s other end.</source>
        <translation>Na lom: ťuknite na druhý koniec čiary lomu.</translation>
    </message>
    <message>
        <source>On fold: tap one end of the fold line, then the other.</source>
        <translation>Na lom: ťuknite na jeden koniec čiary lomu, potom na druhý.</translation>
    </message>
    <message>
        <source>Notch: tap the seam to place one; drag a notch to slide it along the seam.</source>
        <translation>Zárez: ťuknite na šev a zárez sa umiestni; potiahnutím ho posuniete pozdĺž švu.</translation>
    </message>
    <message>
        <source>Drill hole: tap where it goes.</source>
        <translation>Vrtaný otvor: ťuknite tam, kde má byť.</translation>
    </message>
    <message>
        <source>Delete mark: tap a notch, drill hole, grainline or fold line.</source>
        <translation>Zmazať značku: ťuknite na zárez, vrtaný otvor, smer osnovy alebo čiaru lomu.</translation>
    </message>
    <message>
        <source>Seam allowance: tap a seam, then set its width in the bar.</source>
        <translation>Prídavok na šev: ťuknite na šev a potom nastavte jeho šírku v lište.</translation>
    </message>
</context>
<context>
    <name>MessageBanner</name>
    <message>
        <source>Close message</source>
        <translation>Zavrieť správu</translation>
    </message>
    <message>
        <source>Change units…</source>
        <extracomment>Button in the message that a DXF without units was read in the units chosen for such files.</extracomment>
        <translation>Zmeniť jednotky…</translation>
    </message>
</context>
<context>
    <name>NumberStepper</name>
    <message>
        <source>%1 of %2</source>
        <extracomment>Which number of a typed list the − and + buttons change: %1 its place, %2 how many there are.</extracomment>
        <translation>%1 z %2</translation>
    </message>
    <message>
        <source>Previous number</source>
        <extracomment>Screen-reader name: chooses the previous number of the list for the − and + buttons.</extracomment>
        <translation>Predchádzajúce číslo</translation>
    </message>
    <message>
        <source>Next number</source>
        <extracomment>Screen-reader name: chooses the next number of the list for the − and + buttons.</extracomment>
        <translation>Nasledujúce číslo</translation>
    </message>
    <message>
        <source>Decrease the marked number</source>
        <extracomment>Screen-reader name: makes the marked number of the list smaller by the step shown.</extracomment>
        <translation>Zmenšiť označené číslo</translation>
    </message>
    <message>
        <source>Increase the marked number</source>
        <extracomment>Screen-reader name: makes the marked number of the list larger by the step shown.</extracomment>
        <translation>Zväčšiť označené číslo</translation>
    </message>
</context>
<context>
    <name>PanelDrawer</name>
    <message>
        <source>Curves and settings</source>
        <translation>Krivky a nastavenia</translation>
    </message>
    <message>
        <source>Unpin</source>
        <extracomment>Button (verb): let the side panel slide over the canvas instead of staying beside it.</extracomment>
        <translation>Odopnúť</translation>
    </message>
    <message>
        <source>Pin</source>
        <extracomment>Button (verb): keep the side panel open beside the canvas.</extracomment>
        <translation>Pripnúť</translation>
    </message>
    <message>
        <source>Unpin the panel: let it slide over the canvas</source>
        <translation>Odopnúť panel: bude sa vysúvať nad plátno</translation>
    </message>
    <message>
        <source>Pin the panel beside the canvas</source>
        <translation>Pripnúť panel vedľa plátna</translation>
    </message>
</context>
<context>
    <name>PieceBar</name>
    <message>
        <source>Pattern piece</source>
        <extracomment>Title of the bar that edits a garment pattern piece&apos;s marks.</extracomment>
        <translation>Strihový diel</translation>
    </message>
    <message>
        <source>Make a pattern piece</source>
        <translation>Urobiť strihový diel</translation>
    </message>
    <message>
        <source>Select a closed curve: the outline of a pattern piece.</source>
        <translation>Vyberte uzavretú krivku: obrys strihového dielu.</translation>
    </message>
    <message>
        <source>Size</source>
        <extracomment>A garment size (38, M) of the pattern piece.</extracomment>
        <translation>Veľkosť</translation>
    </message>
    <message>
        <source>Cut</source>
        <extracomment>How many pieces to cut from the fabric (“cut 2”).</extracomment>
        <translation>Strihať</translation>
    </message>
    <message>
        <source>How many to cut</source>
        <translation>Koľko strihať</translation>
    </message>
    <message>
        <source>Material</source>
        <extracomment>The fabric the pattern piece is cut from.</extracomment>
        <translation>Materiál</translation>
    </message>
    <message>
        <source>Grainline</source>
        <extracomment>Tool: draw the pattern piece&apos;s grainline with two taps.</extracomment>
        <translation>Smer osnovy</translation>
    </message>
    <message>
        <source>On fold</source>
        <extracomment>Tool: the fold line, the edge laid on the fabric&apos;s fold (two taps).</extracomment>
        <translation>Na lom</translation>
    </message>
    <message>
        <source>Notch</source>
        <extracomment>Tool: place a notch by tapping the seam.</extracomment>
        <translation>Zárez</translation>
    </message>
    <message>
        <source>Slit notch</source>
        <translation>Rovný zárez</translation>
    </message>
    <message>
        <source>V notch</source>
        <translation>Zárez V</translation>
    </message>
    <message>
        <source>Castle notch</source>
        <translation>Obdĺžnikový zárez</translation>
    </message>
    <message>
        <source>Notch kind</source>
        <translation>Druh zárezu</translation>
    </message>
    <message>
        <source>Drill hole</source>
        <extracomment>Tool: mark a drill hole by a tap.</extracomment>
        <translation>Vrtaný otvor</translation>
    </message>
    <message>
        <source>Delete mark</source>
        <extracomment>Tool: delete the notch, drill hole, grainline or fold line tapped.</extracomment>
        <translation>Zmazať značku</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>Hotovo</translation>
    </message>
    <message>
        <source>Close the pattern piece bar</source>
        <translation>Zavrieť panel strihového dielu</translation>
    </message>
    <message>
        <source>Seam allowance</source>
        <extracomment>Tool: tap a seam of the pattern piece to set its own seam allowance width.</extracomment>
        <translation>Prídavok na šev</translation>
    </message>
    <message>
        <source>Seam %1</source>
        <extracomment>The seam tapped (numbered from 1 along the piece) whose seam allowance the bar shows.</extracomment>
        <translation>Šev %1</translation>
    </message>
    <message>
        <source>Seam allowance %1 %2 narrower</source>
        <translation>Prídavok na šev o %1 %2 užší</translation>
    </message>
    <message>
        <source>Seam allowance of the seam</source>
        <translation>Prídavok na tento šev</translation>
    </message>
    <message>
        <source>Seam allowance %1 %2 wider</source>
        <translation>Prídavok na šev o %1 %2 širší</translation>
    </message>
    <message>
        <source>As the piece</source>
        <extracomment>Give the seam the piece&apos;s own seam allowance width again.</extracomment>
        <translation>Ako diel</translation>
    </message>
    <message>
        <source>Hem: turned-back corners</source>
        <extracomment>Toggle: the tapped seam is a hem, so its seam allowance&apos;s corners are turned back (mirrored about the hem line) rather than mitred.</extracomment>
        <translation>Lem: zahnuté rohy</translation>
    </message>
</context>
<context>
    <name>PracticumPlot</name>
    <message>
        <source>Change the segments</source>
        <translation>Zmeniť segmenty</translation>
    </message>
</context>
<context>
    <name>PracticumView</name>
    <message>
        <source>Cubic segments</source>
        <translation>Kubické segmenty</translation>
    </message>
    <message>
        <source>Close</source>
        <extracomment>Button (verb): closes this teaching view and returns to the drawing.</extracomment>
        <translation>Zavrieť</translation>
    </message>
    <message>
        <source>Parametric segment</source>
        <translation>Parametrický segment</translation>
    </message>
    <message>
        <source>Spline through several points</source>
        <translation>Splajn cez viac bodov</translation>
    </message>
    <message>
        <source>Kind of segment</source>
        <translation>Druh segmentu</translation>
    </message>
    <message>
        <source>Lines per segment</source>
        <translation>Počet úsečiek na segment</translation>
    </message>
    <message>
        <source>By lines</source>
        <translation>Úsečkami</translation>
    </message>
    <message>
        <source>By points</source>
        <translation>Bodmi</translation>
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
        <source>Drag the green points, or the grey grips at the ends of the guide vectors to change the end directions.</source>
        <translation>Potiahnite zelené body alebo sivé úchyty na koncoch smerových vektorov: úchytmi meníte smery na koncoch.</translation>
    </message>
    <message>
        <source>Function segment y(x)</source>
        <translation>Funkčný segment y(x)</translation>
    </message>
    <message>
        <source>Test example</source>
        <translation>Testovací príklad</translation>
    </message>
    <message>
        <source>Segment example</source>
        <extracomment>Button: loads the practicum&apos;s single-segment example (KG-202: two points, guide vectors rising and falling at 45°), in the segment kind chosen.</extracomment>
        <translation>Príklad segmentu</translation>
    </message>
</context>
<context>
    <name>PrintDialog</name>
    <message>
        <source>Print pattern</source>
        <translation>Tlač strihu</translation>
    </message>
    <message>
        <source>Print to PDF…</source>
        <translation>Vytlačiť do PDF…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Zrušiť</translation>
    </message>
    <message>
        <source>Paper</source>
        <translation>Papier</translation>
    </message>
    <message>
        <source>Letter</source>
        <extracomment>The US paper size Letter (8.5 × 11 in), not a letter of the alphabet or a message.</extracomment>
        <translation>Letter (USA)</translation>
    </message>
    <message>
        <source>Orientation</source>
        <translation>Orientácia</translation>
    </message>
    <message>
        <source>Automatic (fewer pages)</source>
        <translation>Automaticky (menej listov)</translation>
    </message>
    <message>
        <source>Portrait</source>
        <translation>Na výšku</translation>
    </message>
    <message>
        <source>Landscape</source>
        <translation>Na šírku</translation>
    </message>
    <message>
        <source>Overlap (mm)</source>
        <translation>Prekrytie (mm)</translation>
    </message>
    <message numerus="yes">
        <source>%n page(s) to tape together: %1 × %2 (rows × columns), %3.</source>
        <translation>
            <numerusform>Na zlepenie: %n list, %1 × %2 (riadky × stĺpce), %3.</numerusform>
            <numerusform>Na zlepenie: %n listy, %1 × %2 (riadky × stĺpce), %3.</numerusform>
            <numerusform>Na zlepenie: %n listov, %1 × %2 (riadky × stĺpce), %3.</numerusform>
        </translation>
    </message>
    <message>
        <source>landscape</source>
        <translation>na šírku</translation>
    </message>
    <message>
        <source>portrait</source>
        <translation>na výšku</translation>
    </message>
    <message>
        <source>Before them, a first page with a 10 cm test square and the overview. Print at 100 % (actual size). The visible curves are printed; the background picture is not.</source>
        <translation>Pred nimi je prvý list so skúšobným štvorcom 10 cm a prehľadom. Tlačte v mierke 100 % (skutočná veľkosť). Tlačia sa viditeľné krivky, obrázok na pozadí nie.</translation>
    </message>
    <message>
        <source>The drawing is in px: it is printed at 96 px per inch. Choose real units for true size.</source>
        <translation>Kresba je v pixeloch (px): tlačí sa s 96 px na palec. Ak chcete tlačiť v skutočnej veľkosti, zvoľte fyzické jednotky (mm, cm alebo palce).</translation>
    </message>
</context>
<context>
    <name>SeamAllowanceDialog</name>
    <message>
        <source>Seam allowance</source>
        <translation>Prídavok na šev</translation>
    </message>
    <message>
        <source>Width (%1)</source>
        <extracomment>Label: the seam allowance&apos;s width; %1 is the unit (mm, cm…).</extracomment>
        <translation>Šírka (%1)</translation>
    </message>
    <message>
        <source>Seam allowance width</source>
        <translation>Šírka prídavku na šev</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Strana</translation>
    </message>
    <message>
        <source>Outside</source>
        <translation>Zvonka</translation>
    </message>
    <message>
        <source>Inside</source>
        <translation>Zvnútra</translation>
    </message>
    <message>
        <source>Left of the direction</source>
        <translation>Vľavo od smeru</translation>
    </message>
    <message>
        <source>Right of the direction</source>
        <translation>Vpravo od smeru</translation>
    </message>
    <message>
        <source>Corners</source>
        <translation>Rohy</translation>
    </message>
    <message>
        <source>Mitered</source>
        <translation>Ostré</translation>
    </message>
    <message>
        <source>Bevelled</source>
        <translation>Zrezané</translation>
    </message>
    <message>
        <source>Rounded</source>
        <translation>Zaoblené</translation>
    </message>
    <message>
        <source>Miter limit (%1)</source>
        <extracomment>Label: the longest pointed corner; %1 is the unit (mm, cm…).</extracomment>
        <translation>Limit ostrého rohu (%1)</translation>
    </message>
    <message>
        <source>Miter limit</source>
        <translation>Limit ostrého rohu</translation>
    </message>
    <message>
        <source>Apply</source>
        <extracomment>Button (verb): applies the changed settings to this seam allowance.</extracomment>
        <translation>Použiť</translation>
    </message>
    <message>
        <source>Add</source>
        <extracomment>Button (verb): adds a seam allowance to the selected curve.</extracomment>
        <translation>Pridať</translation>
    </message>
    <message>
        <source>Detach</source>
        <extracomment>Button (verb): cut the link between the seam allowance and its curve, so it can be edited on its own.</extracomment>
        <translation>Odpojiť</translation>
    </message>
    <message>
        <source>Detach from its curve</source>
        <translation>Odpojiť od krivky</translation>
    </message>
    <message>
        <source>Close</source>
        <extracomment>Button (verb): closes this dialog.</extracomment>
        <translation>Zavrieť</translation>
    </message>
    <message>
        <source>Computing the seam allowance…</source>
        <translation>Počíta sa prídavok na šev…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Zrušiť</translation>
    </message>
    <message>
        <source>Cancel the seam allowance</source>
        <translation>Zrušiť výpočet prídavku na šev</translation>
    </message>
</context>
<context>
    <name>SidePanel</name>
    <message>
        <source>Curves</source>
        <translation>Krivky</translation>
    </message>
    <message>
        <source>No curves yet.</source>
        <translation>Zatiaľ žiadne krivky.</translation>
    </message>
    <message>
        <source>%1 · cannot be drawn from these points</source>
        <translation>%1 · z týchto bodov sa nedá nakresliť</translation>
    </message>
    <message numerus="yes">
        <source>%1 · %n point(s) · length %2</source>
        <extracomment>%1 is the curve&apos;s kind, %2 its length with its unit (12.5 mm).</extracomment>
        <translation>
            <numerusform>%1 · %n bod · dĺžka %2</numerusform>
            <numerusform>%1 · %n body · dĺžka %2</numerusform>
            <numerusform>%1 · %n bodov · dĺžka %2</numerusform>
        </translation>
    </message>
    <message>
        <source>Selected curve</source>
        <translation>Vybraná krivka</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Názov</translation>
    </message>
    <message>
        <source>Kind</source>
        <extracomment>Label (noun): the kind of the selected curve, for example “Bézier curve” or “Natural spline”.</extracomment>
        <translation>Druh</translation>
    </message>
    <message>
        <source>degree %1</source>
        <translation>stupeň %1</translation>
    </message>
    <message>
        <source>Parameterization</source>
        <translation>Parametrizácia</translation>
    </message>
    <message>
        <source>Uniform</source>
        <translation>Uniformná</translation>
    </message>
    <message>
        <source>Chord length</source>
        <translation>Podľa dĺžky tetív</translation>
    </message>
    <message>
        <source>Centripetal</source>
        <translation>Centripetálna</translation>
    </message>
    <message>
        <source>Order</source>
        <extracomment>Label (noun): the order k of a B-spline (degree + 1), a number; not a sequence and not a command.</extracomment>
        <translation>Rád splajnu</translation>
    </message>
    <message>
        <source>Node type</source>
        <translation>Typ uzla</translation>
    </message>
    <message>
        <source>Smooth</source>
        <extracomment>Knot type: the handles on both sides stay on one line (G1).</extracomment>
        <translation>Hladký</translation>
    </message>
    <message>
        <source>Symmetric</source>
        <extracomment>Knot type: the handles on both sides stay on one line and have equal lengths (C1).</extracomment>
        <translation>Symetrický</translation>
    </message>
    <message>
        <source>Corner</source>
        <extracomment>Knot type: the handles on both sides move independently (a corner).</extracomment>
        <translation>Ostrý</translation>
    </message>
    <message>
        <source>Colour</source>
        <translation>Farba</translation>
    </message>
    <message>
        <source>Visible</source>
        <translation>Viditeľná</translation>
    </message>
    <message>
        <source>Locked</source>
        <translation>Zamknutá</translation>
    </message>
    <message>
        <source>Close curve</source>
        <translation>Uzavrieť krivku</translation>
    </message>
    <message>
        <source>Move up</source>
        <translation>Posunúť nahor</translation>
    </message>
    <message>
        <source>Move down</source>
        <translation>Posunúť nadol</translation>
    </message>
    <message>
        <source>Delete curve</source>
        <translation>Odstrániť krivku</translation>
    </message>
    <message>
        <source>Coordinates</source>
        <translation>Súradnice</translation>
    </message>
    <message>
        <source>Info</source>
        <extracomment>Heading (noun): figures about the selected curve (length, fit error, continuity).</extracomment>
        <translation>Informácie</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Dĺžka</translation>
    </message>
    <message>
        <source>Fit error (RMS / max)</source>
        <translation>Chyba aproximácie (RMS / max.)</translation>
    </message>
    <message>
        <source>Continuity</source>
        <translation>Spojitosť</translation>
    </message>
    <message>
        <source>joint %1: %2</source>
        <translation>spoj %1: %2</translation>
    </message>
    <message>
        <source>Background image</source>
        <translation>Obrázok na pozadí</translation>
    </message>
    <message>
        <source>Load image…</source>
        <translation>Načítať obrázok…</translation>
    </message>
    <message>
        <source>Show background</source>
        <translation>Zobraziť pozadie</translation>
    </message>
    <message>
        <source>Opacity</source>
        <translation>Nepriehľadnosť</translation>
    </message>
    <message>
        <source>Remove background</source>
        <translation>Odstrániť pozadie</translation>
    </message>
    <message>
        <source>%1 / %2</source>
        <extracomment>The fit error as RMS / maximum: %1 and %2 are numbers.</extracomment>
        <translation>%1 / %2</translation>
    </message>
    <message>
        <source>No curve selected. Tap a curve to edit it.</source>
        <translation>Nie je vybraná žiadna krivka. Ťuknite na krivku a upravte ju.</translation>
    </message>
    <message>
        <source>Curve visible</source>
        <translation>Krivka viditeľná</translation>
    </message>
    <message>
        <source>Curve locked</source>
        <translation>Krivka zamknutá</translation>
    </message>
    <message>
        <source>Curve name</source>
        <translation>Názov krivky</translation>
    </message>
    <message>
        <source>Black</source>
        <translation>Čierna</translation>
    </message>
    <message>
        <source>Red</source>
        <translation>Červená</translation>
    </message>
    <message>
        <source>Blue</source>
        <translation>Modrá</translation>
    </message>
    <message>
        <source>Green</source>
        <translation>Zelená</translation>
    </message>
    <message>
        <source>Orange</source>
        <translation>Oranžová</translation>
    </message>
    <message>
        <source>Purple</source>
        <translation>Fialová</translation>
    </message>
    <message>
        <source>Teal</source>
        <translation>Modrozelená</translation>
    </message>
    <message>
        <source>Brown</source>
        <translation>Hnedá</translation>
    </message>
    <message>
        <source>Colour: %1</source>
        <translation>Farba: %1</translation>
    </message>
    <message>
        <source>Load background image</source>
        <translation>Načítať obrázok na pozadí</translation>
    </message>
    <message>
        <source>Background opacity</source>
        <translation>Nepriehľadnosť pozadia</translation>
    </message>
    <message>
        <source>Pattern piece…</source>
        <extracomment>Opens the bar that makes the closed curve a garment pattern piece and edits its marks.</extracomment>
        <translation>Strihový diel…</translation>
    </message>
    <message>
        <source>Pattern piece</source>
        <translation>Strihový diel</translation>
    </message>
</context>
<context>
    <name>SimplifyDialog</name>
    <message>
        <source>Simplify curve</source>
        <translation>Zjednodušiť krivku</translation>
    </message>
    <message>
        <source>The new curve stays within this distance of the old one.</source>
        <translation>Nová krivka sa od pôvodnej neodchýli viac ako o túto vzdialenosť.</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Tolerancia</translation>
    </message>
    <message>
        <source>Simplify</source>
        <translation>Zjednodušiť</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Zrušiť</translation>
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
        <translation>Zvýšenie stupňa</translation>
    </message>
    <message>
        <source>Compare</source>
        <extracomment>Name of a teaching view (verb used as a title): compare curve kinds or parameterizations side by side.</extracomment>
        <translation>Porovnať</translation>
    </message>
    <message>
        <source>Curvature comb</source>
        <translation>Hrebeň krivosti</translation>
    </message>
    <message>
        <source>Select a Bézier curve.</source>
        <translation>Vyberte Bézierovu krivku.</translation>
    </message>
    <message>
        <source>Select a curve.</source>
        <translation>Vyberte krivku.</translation>
    </message>
    <message>
        <source>t = %1</source>
        <extracomment>The curve parameter t and its value (a number); keep “t”.</extracomment>
        <translation>t = %1</translation>
    </message>
    <message>
        <source>Parameter t</source>
        <translation>Parameter t</translation>
    </message>
    <message numerus="yes">
        <source>degree %1 → %2 (%n point(s))</source>
        <translation>
            <numerusform>stupeň %1 → %2 (%n bod)</numerusform>
            <numerusform>stupeň %1 → %2 (%n body)</numerusform>
            <numerusform>stupeň %1 → %2 (%n bodov)</numerusform>
        </translation>
    </message>
    <message>
        <source>Elevation steps</source>
        <translation>Kroky zvýšenia stupňa</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pozastaviť</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Prehrať</translation>
    </message>
    <message>
        <source>Play or pause the animation (P)</source>
        <translation>Prehrať alebo pozastaviť animáciu (P)</translation>
    </message>
    <message>
        <source>Direction</source>
        <extracomment>Screen-reader name of the button that reverses the direction of the animation (forwards or backwards in t).</extracomment>
        <translation>Smer</translation>
    </message>
    <message>
        <source>Forward; press to go backward</source>
        <translation>Dopredu; stlačením pôjdete dozadu</translation>
    </message>
    <message>
        <source>Backward; press to go forward</source>
        <translation>Dozadu; stlačením pôjdete dopredu</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Rýchlosť</translation>
    </message>
    <message>
        <source>%1×</source>
        <extracomment>Animation speed factor: %1 is a number (0,5 → “0,5×”).</extracomment>
        <translation>%1×</translation>
    </message>
    <message>
        <source>Split at t</source>
        <translation>Rozdeliť v t</translation>
    </message>
    <message>
        <source>Reduce degree</source>
        <translation>Znížiť stupeň</translation>
    </message>
    <message>
        <source>Replace the curve by the closest curve of one degree less</source>
        <translation>Nahradiť krivku najbližšou krivkou o stupeň nižšou</translation>
    </message>
    <message>
        <source>reduction error %1</source>
        <extracomment>Degree reduction: %1 is the largest distance between the curve and its reduced curve (a number).</extracomment>
        <translation>chyba zníženia stupňa %1</translation>
    </message>
    <message>
        <source>Alt+click or long press: add or remove a control point</source>
        <translation>Alt+klik alebo dlhé stlačenie: pridať alebo odobrať kontrolný bod</translation>
    </message>
    <message>
        <source>Curve kinds</source>
        <extracomment>What the Compare view sets side by side: one curve drawn as each kind, or with each parameterization.</extracomment>
        <translation>Druhy kriviek</translation>
    </message>
    <message>
        <source>Parameterizations</source>
        <translation>Parametrizácie</translation>
    </message>
    <message>
        <source>Scale %1</source>
        <extracomment>%1 is the scale factor of the curvature comb (a number such as 2,5).</extracomment>
        <translation>Mierka %1</translation>
    </message>
    <message>
        <source>Comb scale</source>
        <translation>Mierka hrebeňa</translation>
    </message>
    <message>
        <source>All curves</source>
        <translation>Všetky krivky</translation>
    </message>
    <message>
        <source>Close</source>
        <extracomment>Button (verb): closes the teaching view and returns to the drawing.</extracomment>
        <translation>Zavrieť</translation>
    </message>
    <message>
        <source>Leave the teaching view</source>
        <translation>Opustiť výučbové zobrazenie</translation>
    </message>
    <message>
        <source>Split the curve at t into two curves (a spline becomes a composite curve first)</source>
        <translation>Rozdeliť krivku v bode t na dve krivky (splajn sa najprv zmení na zloženú krivku)</translation>
    </message>
    <message>
        <source>One elevation step less</source>
        <translation>O jeden krok zvýšenia stupňa menej</translation>
    </message>
    <message>
        <source>One elevation step more</source>
        <translation>O jeden krok zvýšenia stupňa viac</translation>
    </message>
    <message>
        <source>One step back in t</source>
        <translation>O jeden krok späť v t</translation>
    </message>
    <message>
        <source>One step forward in t</source>
        <translation>O jeden krok vpred v t</translation>
    </message>
</context>
<context>
    <name>TeachingOverlay</name>
    <message>
        <source>%1 (not possible for these points)</source>
        <translation>%1 (pre tieto body nemožné)</translation>
    </message>
</context>
<context>
    <name>TraceBar</name>
    <message>
        <source>Freehand</source>
        <translation>Voľnou rukou</translation>
    </message>
    <message>
        <source>Calibrate</source>
        <translation>Kalibrovať</translation>
    </message>
    <message>
        <source>Measure</source>
        <translation>Merať</translation>
    </message>
    <message>
        <source>Seam length</source>
        <translation>Dĺžka švu</translation>
    </message>
    <message>
        <source>Deviation</source>
        <translation>Odchýlka</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Tolerancia</translation>
    </message>
    <message numerus="yes">
        <source>last stroke: %n segment(s)</source>
        <translation>
            <numerusform>posledný ťah: %n segment</numerusform>
            <numerusform>posledný ťah: %n segmenty</numerusform>
            <numerusform>posledný ťah: %n segmentov</numerusform>
        </translation>
    </message>
    <message>
        <source>Real distance</source>
        <translation>Skutočná vzdialenosť</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Jednotka</translation>
    </message>
    <message>
        <source>Keep the angle</source>
        <translation>Zachovať uhol</translation>
    </message>
    <message>
        <source>Make it horizontal</source>
        <translation>Vodorovne</translation>
    </message>
    <message>
        <source>Make it vertical</source>
        <translation>Zvisle</translation>
    </message>
    <message>
        <source>Alignment</source>
        <translation>Zarovnanie</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Použiť</translation>
    </message>
    <message>
        <source>Distance %1</source>
        <extracomment>%1 is a length with its unit, for example “12,35 mm”.</extracomment>
        <translation>Vzdialenosť %1</translation>
    </message>
    <message>
        <source>Seam %1</source>
        <extracomment>%1 is the seam length with its unit, for example “412,50 mm”.</extracomment>
        <translation>Šev %1</translation>
    </message>
    <message>
        <source>Maximum %1 · mean %2</source>
        <extracomment>Deviation of a traced curve from the reference curve: %1 and %2 are lengths with their unit.</extracomment>
        <translation>Maximum %1 · priemer %2</translation>
    </message>
    <message>
        <source>Snap</source>
        <extracomment>Check box (verb): snap freehand strokes to the edges seen in the picture.</extracomment>
        <translation>Prichytiť</translation>
    </message>
    <message>
        <source>Leave the tracing tool</source>
        <translation>Opustiť nástroj obkresľovania</translation>
    </message>
    <message>
        <source>Move background</source>
        <translation>Posúvať pozadie</translation>
    </message>
    <message>
        <source>Perspective</source>
        <translation>Perspektíva</translation>
    </message>
    <message>
        <source>A4 sheet (210 × 297 mm)</source>
        <translation>Hárok A4 (210 × 297 mm)</translation>
    </message>
    <message>
        <source>A3 sheet (297 × 420 mm)</source>
        <translation>Hárok A3 (297 × 420 mm)</translation>
    </message>
    <message>
        <source>Letter sheet (8.5 × 11 in)</source>
        <translation>Hárok Letter (8,5 × 11 in)</translation>
    </message>
    <message>
        <source>Mat square 1 cm</source>
        <translation>Štvorec podložky 1 cm</translation>
    </message>
    <message>
        <source>Mat square 10 cm</source>
        <translation>Štvorec podložky 10 cm</translation>
    </message>
    <message>
        <source>Mat square 1 in</source>
        <translation>Štvorec podložky 1 palec</translation>
    </message>
    <message>
        <source>Mat square 6 in</source>
        <translation>Štvorec podložky 6 palcov</translation>
    </message>
    <message>
        <source>Other size</source>
        <translation>Iný rozmer</translation>
    </message>
    <message>
        <source>Known rectangle</source>
        <translation>Známy obdĺžnik</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Šírka</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Výška</translation>
    </message>
    <message>
        <source>As marked: landscape</source>
        <translation>Podľa značiek: na šírku</translation>
    </message>
    <message>
        <source>As marked: portrait</source>
        <translation>Podľa značiek: na výšku</translation>
    </message>
    <message>
        <source>As marked</source>
        <translation>Podľa značiek</translation>
    </message>
    <message>
        <source>Portrait</source>
        <translation>Na výšku</translation>
    </message>
    <message>
        <source>Landscape</source>
        <translation>Na šírku</translation>
    </message>
    <message>
        <source>Orientation</source>
        <translation>Orientácia</translation>
    </message>
    <message>
        <source>Clear perspective</source>
        <translation>Zrušiť perspektívu</translation>
    </message>
    <message>
        <source>Trace outline</source>
        <translation>Obkresliť obrys</translation>
    </message>
    <message>
        <source>Snap to edges</source>
        <translation>Prichytiť k okrajom</translation>
    </message>
    <message>
        <source>Snap the stroke to the picture&apos;s edges</source>
        <translation>Prichytiť ťah k okrajom obrázka</translation>
    </message>
    <message>
        <source>Find the sheet</source>
        <translation>Nájsť hárok</translation>
    </message>
    <message>
        <source>Find the sheet in the background image</source>
        <translation>Nájsť hárok na obrázku na pozadí</translation>
    </message>
    <message>
        <source>Estimated error at the far side: %1 mm</source>
        <translation>Odhadovaná chyba na vzdialenej strane: %1 mm</translation>
    </message>
    <message>
        <source>Knots in the last outline: %1</source>
        <translation>Uzly v poslednom obryse: %1</translation>
    </message>
    <message>
        <source>in effect at this zoom: %1</source>
        <extracomment>%1 is the freehand tolerance that applies at the current zoom, with its unit (0,50 mm).</extracomment>
        <translation>platí pri tomto priblížení: %1</translation>
    </message>
</context>
<context>
    <name>TraceOverlay</name>
    <message>
        <source>seam %1</source>
        <extracomment>Label on the canvas: %1 is the seam length with its unit, for example “412,50 mm”.</extracomment>
        <translation>šev %1</translation>
    </message>
    <message>
        <source>max %1</source>
        <extracomment>Label on the canvas: the largest deviation from the reference curve, %1 a length with its unit.</extracomment>
        <translation>max. %1</translation>
    </message>
    <message>
        <source>%1 px on the picture</source>
        <extracomment>%1 is a distance in pixels of the background picture (a number).</extracomment>
        <translation>%1 px na obrázku</translation>
    </message>
</context>
<context>
    <name>UnitsDialog</name>
    <message>
        <source>Units of the drawing</source>
        <translation>Jednotky výkresu</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Zrušiť</translation>
    </message>
    <message>
        <source>“%1” does not say which units its numbers are in. Read them as (asked once for such files):</source>
        <translation>Súbor „%1“ neuvádza, v akých jednotkách sú jeho čísla. Čítať ich ako (pýtame sa raz pre takéto súbory):</translation>
    </message>
    <message>
        <source>Read DXF files that do not say which units their numbers are in as:</source>
        <translation>Súbory DXF, ktoré neuvádzajú, v akých jednotkách sú ich čísla, čítať ako:</translation>
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
        <source>kontur: give at most one file to open.</source>
        <translation>kontur: zadajte najviac jeden súbor na otvorenie.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: no such file.</source>
        <translation>kontur: nedá sa otvoriť „%1“: taký súbor neexistuje.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: its symbolic links form a loop.</source>
        <translation>kontur: nedá sa otvoriť „%1“: jeho symbolické odkazy tvoria slučku.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: permission denied.</source>
        <translation>kontur: nedá sa otvoriť „%1“: prístup zamietnutý.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: it is a folder, not a file.</source>
        <translation>kontur: nedá sa otvoriť „%1“: je to priečinok, nie súbor.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: it is not a regular file (a named pipe or a device).</source>
        <translation>kontur: nedá sa otvoriť „%1“: nie je to bežný súbor (je to pomenovaná rúra alebo zariadenie).</translation>
    </message>
</context>
<context>
    <name>errors</name>
    <message>
        <source>the file does not exist or cannot be read.</source>
        <translation>súbor neexistuje alebo sa nedá prečítať.</translation>
    </message>
    <message>
        <source>the file cannot be written there (a folder that is missing or read-only, or a full disk).</source>
        <translation>súbor sa tam nedá zapísať (priečinok chýba alebo je len na čítanie, alebo je disk plný).</translation>
    </message>
    <message>
        <source>the file is larger than Kontur reads (%1 MB).</source>
        <extracomment>%1 is a size in megabytes, e.g. &quot;1 000&quot;.</extracomment>
        <translation>súbor je väčší, ako dokáže Kontur načítať (%1 MB).</translation>
    </message>
    <message>
        <source>the file holds more points than Kontur reads (%1).</source>
        <extracomment>%1 is a large number of points, e.g. &quot;6 000 000&quot;.</extracomment>
        <translation>súbor obsahuje viac bodov, ako dokáže Kontur načítať (%1).</translation>
    </message>
    <message>
        <source>the file holds more curves than Kontur reads (%1).</source>
        <translation>súbor obsahuje viac kriviek, ako dokáže Kontur načítať (%1).</translation>
    </message>
    <message>
        <source>the file&apos;s structure is nested deeper than %1 levels.</source>
        <extracomment>The file&apos;s elements (JSON or XML) are nested inside each other deeper than %1 levels.</extracomment>
        <translation>hĺbka vnorenia štruktúry súboru presahuje %1.</translation>
    </message>
    <message>
        <source>the file is not text in UTF-8.</source>
        <extracomment>UTF-8 is the name of a text encoding; keep it as it is.</extracomment>
        <translation>súbor nie je text v kódovaní UTF-8.</translation>
    </message>
    <message>
        <source>a number was expected here.</source>
        <translation>tu sa očakávalo číslo.</translation>
    </message>
    <message>
        <source>this number is too large for Kontur, or is not a number.</source>
        <translation>toto číslo je pre Kontur príliš veľké alebo to nie je číslo.</translation>
    </message>
    <message>
        <source>more than a point on this line; in files, numbers are written with a decimal point.</source>
        <extracomment>Shown for &quot;1,5 2,5&quot; in a file: files write numbers with a decimal point.</extracomment>
        <translation>na riadku je viac ako jeden bod; v súboroch sa čísla píšu s desatinnou bodkou.</translation>
    </message>
    <message>
        <source>a word Kontur does not know at the start of this line.</source>
        <translation>na začiatku riadku je slovo, ktoré Kontur nepozná.</translation>
    </message>
    <message>
        <source>this line names a setting but gives no value.</source>
        <translation>riadok uvádza nastavenie, ale nie jeho hodnotu.</translation>
    </message>
    <message>
        <source>a text in quotation marks is not closed.</source>
        <translation>text v úvodzovkách nie je uzavretý.</translation>
    </message>
    <message>
        <source>a curve without points.</source>
        <translation>krivka bez bodov.</translation>
    </message>
    <message>
        <source>the file holds no points.</source>
        <translation>súbor neobsahuje žiadne body.</translation>
    </message>
    <message>
        <source>the first row must be the header “x,y”.</source>
        <extracomment>&quot;x,y&quot; is the first line of the file as it must be written; keep it as it is.</extracomment>
        <translation>prvý riadok musí byť hlavička „x,y“.</translation>
    </message>
    <message>
        <source>each row must hold exactly two values, x and y.</source>
        <translation>každý riadok musí obsahovať presne dve hodnoty, x a y.</translation>
    </message>
    <message>
        <source>a kind of curve this version of Kontur does not know.</source>
        <translation>druh krivky, ktorý táto verzia programu Kontur nepozná.</translation>
    </message>
    <message>
        <source>a parameterization this version of Kontur does not know.</source>
        <translation>parametrizácia, ktorú táto verzia programu Kontur nepozná.</translation>
    </message>
    <message>
        <source>a kind of knot this version of Kontur does not know.</source>
        <translation>druh uzla, ktorý táto verzia programu Kontur nepozná.</translation>
    </message>
    <message>
        <source>the points must be knots or control points.</source>
        <translation>body musia byť uzly alebo kontrolné body.</translation>
    </message>
    <message>
        <source>too few or too many points for this kind of curve.</source>
        <translation>príliš málo alebo príliš veľa bodov pre tento druh krivky.</translation>
    </message>
    <message>
        <source>these points do not suit this kind of curve (knots where control points belong, or the reverse).</source>
        <translation>tieto body sa nehodia k tomuto druhu krivky (uzly namiesto kontrolných bodov alebo naopak).</translation>
    </message>
    <message>
        <source>a value outside its range.</source>
        <translation>hodnota mimo povoleného rozsahu.</translation>
    </message>
    <message>
        <source>the document is damaged: it is not well-formed JSON.</source>
        <translation>dokument je poškodený: nie je to platný JSON.</translation>
    </message>
    <message>
        <source>this is not a Kontur document.</source>
        <translation>toto nie je dokument programu Kontur.</translation>
    </message>
    <message>
        <source>the document was written by a newer version of Kontur.</source>
        <translation>dokument uložila novšia verzia programu Kontur.</translation>
    </message>
    <message>
        <source>a value the document needs is missing.</source>
        <translation>chýba hodnota, ktorú dokument potrebuje.</translation>
    </message>
    <message>
        <source>a value of the wrong type (a number, a text or a list where another belongs).</source>
        <translation>hodnota nesprávneho typu (číslo, text alebo zoznam tam, kde patrí iný typ).</translation>
    </message>
    <message>
        <source>the file is damaged: it is not well-formed XML.</source>
        <translation>súbor je poškodený: nie je to platné XML.</translation>
    </message>
    <message>
        <source>this is not an SVG drawing.</source>
        <translation>toto nie je kresba SVG.</translation>
    </message>
    <message>
        <source>the outline of a shape (its path data) is malformed.</source>
        <translation>obrys tvaru (jeho údaje cesty) je chybný.</translation>
    </message>
    <message>
        <source>a transformation of a shape is malformed.</source>
        <translation>transformácia tvaru je chybná.</translation>
    </message>
    <message>
        <source>the drawing holds no shapes Kontur can draw.</source>
        <translation>kresba neobsahuje žiadne tvary, ktoré Kontur vie nakresliť.</translation>
    </message>
    <message>
        <source>this PDF was not printed by Kontur, so it holds no drawing Kontur can open. Open the .kontur document it came from.</source>
        <translation>toto PDF nevytlačil Kontur, preto neobsahuje kresbu, ktorú by Kontur vedel otvoriť. Otvorte dokument .kontur, z ktorého vzniklo.</translation>
    </message>
    <message>
        <source>the DXF file is damaged or cut short.</source>
        <translation>súbor DXF je poškodený alebo neúplný.</translation>
    </message>
    <message>
        <source>the DXF file holds something Kontur cannot read (a binary DXF, or a shape off the drawing plane).</source>
        <translation>súbor DXF obsahuje niečo, čo Kontur nevie načítať (binárny DXF alebo tvar mimo roviny výkresu).</translation>
    </message>
    <message>
        <source>this kind of curve cannot be written in this format.</source>
        <translation>tento druh krivky sa v tomto formáte nedá zapísať.</translation>
    </message>
    <message>
        <source>too few points for this kind of curve.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>príliš málo bodov pre tento druh krivky.</translation>
    </message>
    <message>
        <source>its knots need at least 4 different positions.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>jej uzly potrebujú aspoň 4 rôzne polohy.</translation>
    </message>
    <message>
        <source>its knots lie too close together to define a curve.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>jej uzly ležia príliš blízko seba na to, aby určili krivku.</translation>
    </message>
    <message>
        <source>a coordinate is too large for Kontur, or is not a number.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>súradnica je pre Kontur príliš veľká alebo to nie je číslo.</translation>
    </message>
    <message>
        <source>its values do not define a curve of its kind.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>jej hodnoty neurčujú krivku jej druhu.</translation>
    </message>
    <message>
        <source>a value out of all proportion to the curve&apos;s size.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>hodnota je neúmerná veľkosti krivky.</translation>
    </message>
    <message>
        <source>it would take more work than Kontur allows for one curve.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>vyžadovalo by to viac práce, ako Kontur dovoľuje pre jednu krivku.</translation>
    </message>
    <message>
        <source>the work was cancelled.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>práca bola zrušená.</translation>
    </message>
    <message>
        <source>line %1, column %2: %3</source>
        <extracomment>Where in a file: %1 the line, %2 the column (character) in it, %3 what is wrong there.</extracomment>
        <translation>riadok %1, stĺpec %2: %3</translation>
    </message>
    <message>
        <source>line %1: %2</source>
        <extracomment>Where in a file: %1 the line, %2 what is wrong there.</extracomment>
        <translation>riadok %1: %2</translation>
    </message>
    <message>
        <source>at %1: %2</source>
        <extracomment>Where in a document: %1 is the place as the file writes it (e.g. curves[3].points[7]), %2 what is wrong.</extracomment>
        <translation>na mieste %1: %2</translation>
    </message>
    <message>
        <source>curve %1: %2</source>
        <extracomment>%1 is the curve&apos;s number in the file (1, 2, …), %2 what is wrong with it.</extracomment>
        <translation>krivka %1: %2</translation>
    </message>
    <message>
        <source>the points do not define a curve (two knots at the same place, or too few different knots).</source>
        <translation>body neurčujú krivku (dva uzly na rovnakom mieste alebo príliš málo rôznych uzlov).</translation>
    </message>
    <message>
        <source>all its points are at the same place.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>všetky jej body sú na rovnakom mieste.</translation>
    </message>
    <message>
        <source>two consecutive knots are at the same place.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>dva po sebe idúce uzly sú na rovnakom mieste.</translation>
    </message>
</context>
<context>
    <name>io</name>
    <message>
        <source>Outline %1</source>
        <extracomment>Automatic name of a curve traced along a piece&apos;s outline in the photo: %1 is a running number.</extracomment>
        <translation>Obrys %1</translation>
    </message>
</context>
<context>
    <name>kontur</name>
    <message>
        <source>Add %1</source>
        <extracomment>Undo text: %1 is the name of the added curve.</extracomment>
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
        <extracomment>Automatic name of a new curve: %1 is a running number (Bézier 3).</extracomment>
        <translation>Bézier %1</translation>
    </message>
    <message>
        <source>Delete %1</source>
        <extracomment>Undo text: %1 is the name of the deleted curve.</extracomment>
        <translation>Odstrániť %1</translation>
    </message>
    <message>
        <source>Reorder curves</source>
        <translation>Zmeniť poradie kriviek</translation>
    </message>
    <message>
        <source>Change background</source>
        <translation>Zmeniť obrázok na pozadí</translation>
    </message>
    <message>
        <source>Cubic through 4 points</source>
        <translation>Kubická krivka cez 4 body</translation>
    </message>
    <message>
        <source>Least-squares cubic</source>
        <translation>Kubická krivka metódou najmenších štvorcov</translation>
    </message>
    <message>
        <source>Composite curve</source>
        <translation>Zložená krivka</translation>
    </message>
    <message>
        <source>Through 4 points %1</source>
        <extracomment>Automatic name of a new cubic through 4 points: %1 is a running number.</extracomment>
        <translation>Cez 4 body %1</translation>
    </message>
    <message>
        <source>Least squares %1</source>
        <extracomment>Automatic name of a new least-squares cubic: %1 is a running number.</extracomment>
        <translation>Najmenšie štvorce %1</translation>
    </message>
    <message>
        <source>Composite %1</source>
        <extracomment>Automatic name of a new composite curve: %1 is a running number.</extracomment>
        <translation>Zložená %1</translation>
    </message>
    <message>
        <source>Change parameterization</source>
        <translation>Zmeniť parametrizáciu</translation>
    </message>
    <message>
        <source>Rename curve</source>
        <translation>Premenovať krivku</translation>
    </message>
    <message>
        <source>Change colour</source>
        <translation>Zmeniť farbu</translation>
    </message>
    <message>
        <source>Show curve</source>
        <translation>Zobraziť krivku</translation>
    </message>
    <message>
        <source>Hide curve</source>
        <translation>Skryť krivku</translation>
    </message>
    <message>
        <source>Lock curve</source>
        <translation>Zamknúť krivku</translation>
    </message>
    <message>
        <source>Unlock curve</source>
        <translation>Odomknúť krivku</translation>
    </message>
    <message>
        <source>Change node type</source>
        <translation>Zmeniť typ uzla</translation>
    </message>
    <message>
        <source>Add point</source>
        <translation>Pridať bod</translation>
    </message>
    <message>
        <source>Delete point</source>
        <translation>Odstrániť bod</translation>
    </message>
    <message>
        <source>Insert knot</source>
        <translation>Vložiť uzol</translation>
    </message>
    <message>
        <source>Close curve</source>
        <translation>Uzavrieť krivku</translation>
    </message>
    <message>
        <source>Edit coordinates</source>
        <translation>Upraviť súradnice</translation>
    </message>
    <message>
        <source>Reset all</source>
        <translation>Vymazať všetko</translation>
    </message>
    <message>
        <source>Natural spline</source>
        <translation>Prirodzený splajn</translation>
    </message>
    <message>
        <source>Clamped spline</source>
        <extracomment>Curve kind: the cubic spline with given first derivatives at both ends (a complete or clamped spline).</extracomment>
        <translatorcomment>clamped splajn: the term of the Košice course (glossary); in prose a teacher says splajn s danými deriváciami na koncoch.</translatorcomment>
        <translation>Clamped splajn</translation>
    </message>
    <message>
        <source>Not-a-knot spline</source>
        <extracomment>Curve kind: the cubic spline whose second and next-to-last knots are not knots (the third derivative is continuous there).</extracomment>
        <translation>Splajn s podmienkou „nie uzol“ (not-a-knot)</translation>
    </message>
    <message>
        <source>Periodic spline</source>
        <translation>Periodický splajn</translation>
    </message>
    <message>
        <source>Catmull–Rom spline</source>
        <translation>Catmull–Romov splajn</translation>
    </message>
    <message>
        <source>Hermite spline</source>
        <translation>Hermitov splajn</translation>
    </message>
    <message>
        <source>B-spline</source>
        <translation>B-splajn</translation>
    </message>
    <message>
        <source>Global B-spline</source>
        <translation>Globálny B-splajn</translation>
    </message>
    <message>
        <source>Interpolating polynomial</source>
        <translation>Interpolačný polynóm</translation>
    </message>
    <message>
        <source>Function spline y(x)</source>
        <translation>Funkčný splajn y(x)</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <extracomment>Automatic name of a new curve: %1 is its kind (“Natural spline”), %2 a running number.</extracomment>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>Change order</source>
        <translation>Zmeniť rád splajnu</translation>
    </message>
    <message>
        <source>Untitled</source>
        <extracomment>The name of a document that has not been saved yet (also the suggested file name).</extracomment>
        <translation>Bez názvu</translation>
    </message>
    <message>
        <source>Import %1</source>
        <extracomment>Undo text: %1 is the name of the imported file.</extracomment>
        <translation>Importovať %1</translation>
    </message>
    <message>
        <source>Split curve</source>
        <translation>Rozdeliť krivku</translation>
    </message>
    <message>
        <source>uniform</source>
        <extracomment>Parameterization name in lower case, shown after a kind name (“Natural spline, uniform”).</extracomment>
        <translation>uniformná</translation>
    </message>
    <message>
        <source>chord length</source>
        <extracomment>Parameterization name in lower case, shown after a kind name (“Natural spline, chord length”).</extracomment>
        <translation>podľa dĺžky tetív</translation>
    </message>
    <message>
        <source>centripetal</source>
        <extracomment>Parameterization name in lower case, shown after a kind name (“Natural spline, centripetal”).</extracomment>
        <translation>centripetálna</translation>
    </message>
    <message>
        <source>Reduce degree</source>
        <translation>Znížiť stupeň</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <extracomment>Legend in the Compare view: %1 is a curve kind, %2 a parameterization (“Natural spline, uniform”).</extracomment>
        <translation>%1, %2</translation>
    </message>
    <message>
        <source>Contour curve (midpoint joins)</source>
        <extracomment>Curve kind: quadratic Bézier pieces through the midpoints of the polygon&apos;s sides, joined smoothly there.</extracomment>
        <translation>Obrysová krivka (spoje v stredoch)</translation>
    </message>
    <message>
        <source>Nothing to print: no curve is visible.</source>
        <translation>Nie je čo tlačiť: žiadna krivka nie je viditeľná.</translation>
    </message>
    <message>
        <source>The drawing would need more than %1 pages at true size. Check the document&apos;s units.</source>
        <translation>Kresba by v skutočnej veľkosti potrebovala viac ako %1 listov. Skontrolujte jednotky dokumentu.</translation>
    </message>
    <message>
        <source>The drawing cannot be printed: %1</source>
        <translation>Kresbu nemožno vytlačiť: %1</translation>
    </message>
    <message>
        <source>%1 seam allowance</source>
        <extracomment>Name of a new seam allowance: %1 is the name of its curve.</extracomment>
        <translation>%1 – prídavok na šev</translation>
    </message>
    <message>
        <source>Add seam allowance</source>
        <translation>Pridať prídavok na šev</translation>
    </message>
    <message>
        <source>Change seam allowance</source>
        <translation>Zmeniť prídavok na šev</translation>
    </message>
    <message>
        <source>Detach seam allowance</source>
        <translation>Odpojiť prídavok na šev</translation>
    </message>
    <message>
        <source>no file name was given</source>
        <translation>nebol zadaný názov súboru</translation>
    </message>
</context>
<context>
    <name>kontur::FunctionSplinePlot</name>
    <message>
        <source>Function values: “%1” is not a number.</source>
        <translation>Funkčné hodnoty: „%1“ nie je číslo.</translation>
    </message>
    <message>
        <source>Function values: give between 2 and %1 numbers.</source>
        <translation>Funkčné hodnoty: zadajte 2 až %1 čísel.</translation>
    </message>
    <message>
        <source>Interval: “%1” is not a number.</source>
        <translation>Interval: „%1“ nie je číslo.</translation>
    </message>
    <message>
        <source>Interval: give two numbers, the smaller first.</source>
        <translation>Interval: zadajte dve čísla, najprv menšie.</translation>
    </message>
    <message>
        <source>Knots: “%1” is not a number.</source>
        <translation>Uzly: „%1“ nie je číslo.</translation>
    </message>
    <message numerus="yes">
        <source>Knots: give %n number(s), one per function value.</source>
        <translation>
            <numerusform>Uzly: zadajte %n číslo, jedno pre každú funkčnú hodnotu.</numerusform>
            <numerusform>Uzly: zadajte %n čísla, jedno pre každú funkčnú hodnotu.</numerusform>
            <numerusform>Uzly: zadajte %n čísel, jedno pre každú funkčnú hodnotu.</numerusform>
        </translation>
    </message>
    <message>
        <source>Knots: each knot must be greater than the one before.</source>
        <translation>Uzly: každý uzol musí byť väčší ako predchádzajúci.</translation>
    </message>
    <message>
        <source>Derivatives: “%1” is not a number.</source>
        <translation>Derivácie: „%1“ nie je číslo.</translation>
    </message>
    <message numerus="yes">
        <source>Derivatives: give %n number(s), one per knot.</source>
        <translation>
            <numerusform>Derivácie: zadajte %n číslo, jedno pre každý uzol.</numerusform>
            <numerusform>Derivácie: zadajte %n čísla, jedno pre každý uzol.</numerusform>
            <numerusform>Derivácie: zadajte %n čísel, jedno pre každý uzol.</numerusform>
        </translation>
    </message>
    <message>
        <source>Derivatives: give two numbers, at the first and the last knot.</source>
        <translation>Derivácie: zadajte dve čísla, v prvom a v poslednom uzle.</translation>
    </message>
    <message>
        <source>Values P at the inner knots: %1</source>
        <translation>Hodnoty P vo vnútorných uzloch: %1</translation>
    </message>
    <message>
        <source>Slopes y′ at the knots: %1</source>
        <translation>Smernice y′ v uzloch: %1</translation>
    </message>
    <message>
        <source>Polynomial of degree %1: it differs from the spline by up to %2.</source>
        <translation>Polynóm stupňa %1: od splajnu sa líši až o %2.</translation>
    </message>
    <message numerus="yes">
        <source>The polynomial is drawn for at most %n point(s).</source>
        <translation>
            <numerusform>Polynóm sa kreslí najviac pre %n bod.</numerusform>
            <numerusform>Polynóm sa kreslí najviac pre %n body.</numerusform>
            <numerusform>Polynóm sa kreslí najviac pre %n bodov.</numerusform>
        </translation>
    </message>
    <message>
        <source>polynomial</source>
        <extracomment>Legend label (noun): the interpolating polynomial drawn beside the spline.</extracomment>
        <translation>polynóm</translation>
    </message>
    <message>
        <source>spline</source>
        <extracomment>Legend label (noun): the spline.</extracomment>
        <translation>splajn</translation>
    </message>
    <message>
        <source>Török&apos;s procedure needs evenly spaced knots: the classical system is drawn.</source>
        <translation>Törökova metóda potrebuje rovnomerne rozložené uzly: zobrazuje sa riešenie klasickej sústavy.</translation>
    </message>
    <message>
        <source>Török&apos;s half-size system and the classical system agree: their slopes differ by at most %1.</source>
        <translation>Törökova sústava polovičnej veľkosti a klasická sústava sa zhodujú: ich derivácie sa líšia najviac o %1.</translation>
    </message>
    <message>
        <source>Add the function spline to the document</source>
        <translation>Pridať funkčný splajn do dokumentu</translation>
    </message>
    <message numerus="yes">
        <source>Knots: give %n number(s), four more than the number of values.</source>
        <translation>
            <numerusform>Uzly: zadajte %n číslo, o štyri viac, ako je hodnôt.</numerusform>
            <numerusform>Uzly: zadajte %n čísla, o štyri viac, ako je hodnôt.</numerusform>
            <numerusform>Uzly: zadajte %n čísel, o štyri viac, ako je hodnôt.</numerusform>
        </translation>
    </message>
    <message>
        <source>Control values b: %1</source>
        <extracomment>b are the global B-spline&apos;s control values, as the course writes them (one per bell Bs).</extracomment>
        <translation>Riadiace hodnoty b: %1</translation>
    </message>
    <message>
        <source>Török&apos;s half-size system and the classical system agree: their slopes differ by less than 10⁻¹⁵ (rounding).</source>
        <translation>Törökova sústava polovičnej veľkosti a klasická sústava sa zhodujú: ich derivácie sa líšia o menej než 10⁻¹⁵ (zaokrúhlenie).</translation>
    </message>
    <message>
        <source>P(%1) = %2</source>
        <extracomment>One value of the spline: P(1,5) = 0,075 (%1 is x, %2 the value).</extracomment>
        <translation>P(%1) = %2</translation>
    </message>
    <message>
        <source>Between the knots: %1</source>
        <extracomment>The spline&apos;s values halfway between the knots, e.g. &quot;P(1,5) = 0,075; P(2,5) = 1,175&quot;.</extracomment>
        <translation>Medzi uzlami: %1</translation>
    </message>
</context>
<context>
    <name>kontur::PieceEdits</name>
    <message>
        <source>There is no other open composite curve to join.</source>
        <translation>Nie je tu iná otvorená zložená krivka na spojenie.</translation>
    </message>
    <message>
        <source>No curve with fewer knots stays within that tolerance.</source>
        <translation>Žiadna krivka s menším počtom uzlov sa nezmestí do tejto tolerancie.</translation>
    </message>
    <message>
        <source>Type a tolerance greater than zero.</source>
        <translation>Zadajte toleranciu väčšiu ako nula.</translation>
    </message>
    <message>
        <source>This works on composite curves that are not locked.</source>
        <translation>Funguje to na zložených krivkách, ktoré nie sú zamknuté.</translation>
    </message>
    <message>
        <source>Make line</source>
        <translation>Narovnať segment</translation>
    </message>
    <message>
        <source>Join curves</source>
        <translation>Spojiť krivky</translation>
    </message>
    <message>
        <source>Simplify curve</source>
        <translation>Zjednodušiť krivku</translation>
    </message>
    <message>
        <source>Extend curve</source>
        <translation>Predĺžiť krivku</translation>
    </message>
</context>
<context>
    <name>kontur::PieceMarkEdits</name>
    <message>
        <source>A pattern piece is a closed curve: close the curve first.</source>
        <translation>Strihový diel je uzavretá krivka: najprv krivku uzavrite.</translation>
    </message>
    <message>
        <source>Select a pattern piece first.</source>
        <translation>Najprv vyberte strihový diel.</translation>
    </message>
    <message>
        <source>Type how many to cut: a whole number from 1 up.</source>
        <translation>Napíšte, koľko strihať: celé číslo od 1.</translation>
    </message>
    <message>
        <source>The two points are too close together: tap two points farther apart.</source>
        <translation>Tieto dva body sú príliš blízko: ťuknite na dva vzdialenejšie body.</translation>
    </message>
    <message>
        <source>There is no mark there.</source>
        <translation>Nie je tam žiadna značka.</translation>
    </message>
    <message>
        <source>Make a pattern piece</source>
        <translation>Urobiť strihový diel</translation>
    </message>
    <message>
        <source>No longer a pattern piece</source>
        <translation>Už nie je strihový diel</translation>
    </message>
    <message>
        <source>Set the piece&apos;s size</source>
        <translation>Nastaviť veľkosť dielu</translation>
    </message>
    <message>
        <source>Set how many to cut</source>
        <translation>Nastaviť, koľko strihať</translation>
    </message>
    <message>
        <source>Set the piece&apos;s material</source>
        <translation>Nastaviť materiál dielu</translation>
    </message>
    <message>
        <source>Draw the grainline</source>
        <translation>Nakresliť smer osnovy</translation>
    </message>
    <message>
        <source>Place on fold</source>
        <translation>Položiť na lom</translation>
    </message>
    <message>
        <source>Add a notch</source>
        <translation>Pridať zárez</translation>
    </message>
    <message>
        <source>Move a notch</source>
        <translation>Posunúť zárez</translation>
    </message>
    <message>
        <source>Change a notch</source>
        <translation>Zmeniť zárez</translation>
    </message>
    <message>
        <source>Add a drill hole</source>
        <translation>Pridať vrtaný otvor</translation>
    </message>
    <message>
        <source>Move a drill hole</source>
        <translation>Posunúť vrtaný otvor</translation>
    </message>
    <message>
        <source>Delete a mark</source>
        <translation>Zmazať značku</translation>
    </message>
</context>
<context>
    <name>kontur::PracticumPlot</name>
    <message>
        <source>The end points have the same x: there is no function segment.</source>
        <translation>Koncové body majú rovnaké x: funkčný segment neexistuje.</translation>
    </message>
    <message>
        <source>A vertical guide vector has no slope dy/dx: a function segment needs one.</source>
        <translation>Zvislý smerový vektor nemá smernicu dy/dx: funkčný segment ju potrebuje.</translation>
    </message>
    <message>
        <source>t = x1 − x0 = %1; k0 = %2; k1 = %3; a3 = %4; a4 = %5</source>
        <translation>t = x1 − x0 = %1; k0 = %2; k1 = %3; a3 = %4; a4 = %5</translation>
    </message>
    <message>
        <source>The end points coincide or a guide vector has no length.</source>
        <translation>Koncové body splývajú alebo smerový vektor nemá dĺžku.</translation>
    </message>
    <message>
        <source>t2 = |P1 − P0| = %1; P0′ = %2; P1′ = %3; a3 = %4; a4 = %5</source>
        <translation>t2 = |P1 − P0| = %1; P0′ = %2; P1′ = %3; a3 = %4; a4 = %5</translation>
    </message>
    <message>
        <source>Two neighbouring points coincide or a guide vector has no length.</source>
        <translation>Dva susedné body splývajú alebo smerový vektor nemá dĺžku.</translation>
    </message>
    <message>
        <source>Chords T: %1
Tangents K: %2</source>
        <extracomment>Two lines of figures: %1 the chord lengths T, %2 the tangent lengths K of the segments (numbers).</extracomment>
        <translation>Tetivy T: %1
Dotyčnice K: %2</translation>
    </message>
</context>
<context>
    <name>kontur::SeamWidths</name>
    <message>
        <source>The piece has no seam allowance yet: add one first.</source>
        <translation>Diel ešte nemá prídavok na šev: najprv ho pridajte.</translation>
    </message>
    <message>
        <source>Tap a seam of the piece first.</source>
        <translation>Najprv ťuknite na šev dielu.</translation>
    </message>
    <message>
        <source>Type the seam allowance: a number from 0 up.</source>
        <translation>Zadajte prídavok na šev: číslo od 0.</translation>
    </message>
    <message>
        <source>The seam allowance cannot be that wide on this piece.</source>
        <translation>Prídavok na šev nemôže byť na tomto diele taký široký.</translation>
    </message>
    <message>
        <source>Set a seam&apos;s allowance</source>
        <translation>Nastaviť prídavok na šev</translation>
    </message>
    <message>
        <source>Set a hem&apos;s corners</source>
        <translation>Nastaviť rohy lemu</translation>
    </message>
</context>
<context>
    <name>kontur::TraceController</name>
    <message>
        <source>Calibrate background</source>
        <translation>Kalibrovať pozadie</translation>
    </message>
    <message>
        <source>The tolerance must be a positive number.</source>
        <translation>Tolerancia musí byť kladné číslo.</translation>
    </message>
    <message>
        <source>Draw along the contour with one finger, a stylus or the mouse.</source>
        <translation>Ťahajte pozdĺž obrysu jedným prstom, perom alebo myšou.</translation>
    </message>
    <message>
        <source>The stroke could not be fitted.</source>
        <translation>Ťah sa nepodarilo aproximovať krivkou.</translation>
    </message>
    <message>
        <source>Traced %1</source>
        <extracomment>Automatic name of a curve drawn freehand over the picture: %1 is a running number.</extracomment>
        <translation>Obkreslená %1</translation>
    </message>
    <message>
        <source>Freehand curve</source>
        <translation>Krivka nakreslená voľnou rukou</translation>
    </message>
    <message>
        <source>Load a background picture first.</source>
        <translation>Najprv načítajte obrázok na pozadí.</translation>
    </message>
    <message>
        <source>Tap a knot of the curve.</source>
        <translation>Ťuknite na uzol krivky.</translation>
    </message>
    <message>
        <source>Tap a curve.</source>
        <translation>Ťuknite na krivku.</translation>
    </message>
    <message>
        <source>Tap a second, different curve.</source>
        <translation>Ťuknite na druhú, inú krivku.</translation>
    </message>
    <message>
        <source>This kind of curve has no knots to measure between.</source>
        <translation>Tento druh krivky nemá uzly, medzi ktorými by sa dalo merať.</translation>
    </message>
    <message>
        <source>These curves cannot be compared.</source>
        <translation>Tieto krivky sa nedajú porovnať.</translation>
    </message>
    <message>
        <source>Tap two points on the picture first.</source>
        <translation>Najprv ťuknite na dva body na obrázku.</translation>
    </message>
    <message>
        <source>Type the real distance between the two points as a positive number.</source>
        <translation>Zadajte skutočnú vzdialenosť medzi dvoma bodmi ako kladné číslo.</translation>
    </message>
    <message>
        <source>The background is locked. Unlock it to calibrate again.</source>
        <translation>Pozadie je zamknuté. Odomknite ho, ak chcete znova kalibrovať.</translation>
    </message>
    <message>
        <source>Choose mm, cm or in.</source>
        <translation>Zvoľte mm, cm alebo palce.</translation>
    </message>
    <message>
        <source>The two points must be different.</source>
        <translation>Oba body musia byť rôzne.</translation>
    </message>
    <message>
        <source>Curve &quot;%1&quot; cannot be turned; calibrate without aligning.</source>
        <translation>Krivku „%1“ nemožno otočiť; kalibrujte bez zarovnania.</translation>
    </message>
    <message>
        <source>Draw along the contour with one finger, a stylus or the mouse; two fingers zoom.</source>
        <translation>Ťahajte pozdĺž obrysu jedným prstom, perom alebo myšou; dvoma prstami sa približuje.</translation>
    </message>
    <message>
        <source>Tap two points on the picture whose real distance you know.</source>
        <translation>Ťuknite na dva body obrázka, ktorých skutočnú vzdialenosť poznáte.</translation>
    </message>
    <message>
        <source>Type the real distance between the two points.</source>
        <translation>Zadajte skutočnú vzdialenosť medzi dvoma bodmi.</translation>
    </message>
    <message>
        <source>Tap two points to measure the straight distance.</source>
        <translation>Ťuknite na dva body a zmerajte vzdialenosť vzdušnou čiarou.</translation>
    </message>
    <message>
        <source>Tap two knots of one curve to measure the length along it.</source>
        <translation>Ťuknite na dva uzly jednej krivky a zmerajte dĺžku pozdĺž nej.</translation>
    </message>
    <message>
        <source>Tap the traced curve, then the reference curve.</source>
        <translation>Ťuknite na obkreslenú krivku, potom na referenčnú krivku.</translation>
    </message>
    <message>
        <source>Drag the picture to move it; two fingers zoom.</source>
        <translation>Potiahnutím obrázok posuniete; dvoma prstami sa približuje.</translation>
    </message>
    <message>
        <source>The background is locked. Unlock it to move it.</source>
        <translation>Pozadie je zamknuté. Odomknite ho, ak ho chcete posunúť.</translation>
    </message>
    <message>
        <source>Tap the four corners of the rectangle first.</source>
        <translation>Najprv ťuknite na štyri rohy obdĺžnika.</translation>
    </message>
    <message>
        <source>Type the rectangle&apos;s width and height as positive numbers.</source>
        <translation>Zadajte šírku a výšku obdĺžnika ako kladné čísla.</translation>
    </message>
    <message>
        <source>The picture has a perspective calibration. Clear it to calibrate by two points.</source>
        <translation>Obrázok má kalibráciu perspektívy. Zrušte ju, ak chcete kalibrovať podľa dvoch bodov.</translation>
    </message>
    <message>
        <source>There the corners would not make a rectangle; the corner stays where it was.</source>
        <translation>Tam by rohy netvorili obdĺžnik; roh zostáva, kde bol.</translation>
    </message>
    <message>
        <source>Drag a corner onto the rectangle&apos;s corner in the picture, or tap four new corners.</source>
        <translation>Potiahnite roh na roh obdĺžnika na obrázku alebo ťuknite na štyri nové rohy.</translation>
    </message>
    <message>
        <source>Tap the four corners of a rectangle whose size you know, in any order.</source>
        <translation>Ťuknite v ľubovoľnom poradí na štyri rohy obdĺžnika, ktorého rozmery poznáte.</translation>
    </message>
    <message>
        <source>Choose the rectangle&apos;s size and apply; drag a corner to refine it.</source>
        <translation>Vyberte rozmer obdĺžnika a použite ho; potiahnutím rohu ho spresníte.</translation>
    </message>
    <message>
        <source>Calibrate perspective</source>
        <translation>Kalibrovať perspektívu</translation>
    </message>
    <message>
        <source>Refine perspective corner</source>
        <translation>Spresniť roh perspektívy</translation>
    </message>
    <message>
        <source>Outline %1</source>
        <extracomment>Automatic name of a curve traced along a piece&apos;s outline in the photo: %1 is a running number.</extracomment>
        <translation>Obrys %1</translation>
    </message>
    <message>
        <source>Trace outline</source>
        <translation>Obkresliť obrys</translation>
    </message>
    <message>
        <source>The background picture cannot be read.</source>
        <translation>Obrázok na pozadí sa nedá prečítať.</translation>
    </message>
    <message>
        <source>No sheet found in the picture (a white rectangle with four straight, clear edges). Tap its four corners instead.</source>
        <translation>Na obrázku sa nenašiel hárok (biely obdĺžnik so štyrmi rovnými, zreteľnými okrajmi). Ťuknite namiesto toho na jeho štyri rohy.</translation>
    </message>
    <message>
        <source>No corner found near the mark; it stays where you dropped it.</source>
        <translation>Pri značke sa nenašiel roh; zostáva tam, kam ste ju pustili.</translation>
    </message>
    <message>
        <source>The calibration may be off by %1 mm at the far side of the picture. Find the sheet again or refine its corners.</source>
        <translation>Kalibrácia sa na vzdialenej strane obrázka môže odchyľovať o %1 mm. Nájdite hárok znova alebo spresnite jeho rohy.</translation>
    </message>
    <message>
        <source>No pattern piece found there. Tap inside a piece that stands out from the table.</source>
        <translation>Nenašiel sa tam žiadny diel strihu. Ťuknite dovnútra dielu, ktorý sa odlišuje od stola.</translation>
    </message>
    <message>
        <source>The outline could not be made into a curve.</source>
        <translation>Obrys sa nepodarilo premeniť na krivku.</translation>
    </message>
    <message>
        <source>No edge found along the stroke; it was fitted as drawn.</source>
        <translation>Pozdĺž ťahu sa nenašiel okraj; ťah bol aproximovaný tak, ako bol nakreslený.</translation>
    </message>
    <message>
        <source>Tap inside a pattern piece on the picture to trace its outline.</source>
        <translation>Ťuknite dovnútra dielu strihu na obrázku, aby ste obkreslili jeho obrys.</translation>
    </message>
    <message>
        <source>The four points are not the corners of a rectangle seen in the picture. Tap them again.</source>
        <translation>Tieto štyri body nie sú rohy obdĺžnika na obrázku. Ťuknite na ne znova.</translation>
    </message>
    <message>
        <source>The sheet in the picture is not flat: its edges bend. Lay it flat and take the photo again, or tap its four corners.</source>
        <translation>Hárok na obrázku nie je rovný: jeho okraje sa ohýbajú. Položte ho naplocho a znova ho odfotografujte alebo ťuknite na jeho štyri rohy.</translation>
    </message>
    <message>
        <source>The rectangle found is about %1 : 1, the chosen one %2 : 1. Choose the sheet&apos;s size, or tap its four corners.</source>
        <extracomment>%1 and %2 are proportions, long side to short side, such as 2.35 and 1.41.</extracomment>
        <translation>Nájdený obdĺžnik má pomer strán asi %1 : 1, zvolený %2 : 1. Zvoľte veľkosť hárka alebo ťuknite na jeho štyri rohy.</translation>
    </message>
</context>
<context>
    <name>kontur::cli</name>
    <message>
        <source>%1: several curves in the file (%2); the points of the first one (line %3) are read</source>
        <translation>%1: súbor obsahuje viac kriviek (%2); načítajú sa body prvej z nich (riadok %3)</translation>
    </message>
    <message>
        <source>unexpected argument &quot;%1&quot;</source>
        <translation>neočakávaný argument „%1“</translation>
    </message>
    <message>
        <source>--in FILE is required</source>
        <translation>--in SÚBOR je povinný</translation>
    </message>
    <message>
        <source>Fit a cubic Bézier curve to points (one &quot;x y&quot; per line).</source>
        <translation>Preložiť body kubickou Bézierovou krivkou (jedno „x y“ na riadok).</translation>
    </message>
    <message>
        <source>interpolate (exactly 4 points) or least-squares.</source>
        <translation>interpolate (presne 4 body) alebo least-squares.</translation>
    </message>
    <message>
        <source>uniform, chord or centripetal.</source>
        <translation>uniform, chord alebo centripetal.</translation>
    </message>
    <message>
        <source>The points file.</source>
        <translation>Súbor s bodmi.</translation>
    </message>
    <message>
        <source>unknown --method &quot;%1&quot; (interpolate or least-squares)</source>
        <translation>neznámy --method „%1“ (interpolate alebo least-squares)</translation>
    </message>
    <message>
        <source>unknown --param &quot;%1&quot; (uniform, chord or centripetal)</source>
        <translation>neznámy --param „%1“ (uniform, chord alebo centripetal)</translation>
    </message>
    <message>
        <source>--reparameterize needs a non-negative integer</source>
        <translation>--reparameterize potrebuje nezáporné celé číslo</translation>
    </message>
    <message>
        <source>%1: %2 points; interpolate needs exactly 4</source>
        <extracomment>%1 is a file name, %2 the number of points in it.</extracomment>
        <translation>%1: počet bodov %2; interpolate potrebuje presne 4</translation>
    </message>
    <message>
        <source>The control points file.</source>
        <translation>Súbor s kontrolnými bodmi.</translation>
    </message>
    <message>
        <source>Elevate the degree R times.</source>
        <translation>Zvýšiť stupeň R-krát.</translation>
    </message>
    <message>
        <source>Evaluate at t1,t2,…</source>
        <translation>Vyhodnotiť v t1,t2,…</translation>
    </message>
    <message>
        <source>Arc length to this absolute accuracy.</source>
        <translation>Dĺžka oblúka s touto absolútnou presnosťou.</translation>
    </message>
    <message>
        <source>Nearest point to x,y.</source>
        <translation>Najbližší bod k x,y.</translation>
    </message>
    <message>
        <source>The tight bounding box.</source>
        <translation>Tesný ohraničujúci obdĺžnik.</translation>
    </message>
    <message>
        <source>--elevate needs an integer from 0 to 10000</source>
        <translation>--elevate potrebuje celé číslo od 0 do 10000</translation>
    </message>
    <message>
        <source>--at needs numbers separated by commas</source>
        <translation>--at potrebuje čísla oddelené čiarkami</translation>
    </message>
    <message>
        <source>--length needs a positive accuracy</source>
        <translation>--length potrebuje kladnú presnosť</translation>
    </message>
    <message>
        <source>--nearest needs x,y</source>
        <translation>--nearest potrebuje x,y</translation>
    </message>
    <message>
        <source>Build the composite curve through the knots in the file.</source>
        <translation>Zostrojiť zloženú krivku cez uzly zo súboru.</translation>
    </message>
    <message>
        <source>The knots file.</source>
        <translation>Súbor s uzlami.</translation>
    </message>
    <message>
        <source>Close the curve.</source>
        <translation>Uzavrieť krivku.</translation>
    </message>
    <message>
        <source>Relative tolerance of the continuity report (default 1e-9).</source>
        <translation>Relatívna tolerancia správy o spojitosti (predvolene 1e-9).</translation>
    </message>
    <message>
        <source>--tolerance needs a non-negative number</source>
        <translation>--tolerance potrebuje nezáporné číslo</translation>
    </message>
    <message numerus="yes">
        <source>expected %n file name(s), got %1</source>
        <translation>
            <numerusform>očakával sa %n názov súboru, počet zadaných: %1</numerusform>
            <numerusform>očakávali sa %n názvy súborov, počet zadaných: %1</numerusform>
            <numerusform>očakávalo sa %n názvov súborov, počet zadaných: %1</numerusform>
        </translation>
    </message>
    <message>
        <source>The input file.</source>
        <translation>Vstupný súbor.</translation>
    </message>
    <message>
        <source>The output file.</source>
        <translation>Výstupný súbor.</translation>
    </message>
    <message>
        <source>Kind of curve for points without one (default composite).</source>
        <translation>Druh krivky pre body, ktoré ho nemajú určený (predvolene composite).</translation>
    </message>
    <message>
        <source>Parameterization for fitted kinds (default chord).</source>
        <translation>Parametrizácia pre prekladané druhy (predvolene chord).</translation>
    </message>
    <message>
        <source>Write only curve N (0-based).</source>
        <translation>Zapísať iba krivku N (od 0).</translation>
    </message>
    <message>
        <source>unknown --kind &quot;%1&quot;</source>
        <translation>neznámy --kind „%1“</translation>
    </message>
    <message>
        <source>--curve needs a curve number from 0 to %1</source>
        <translation>--curve potrebuje číslo krivky od 0 do %1</translation>
    </message>
    <message>
        <source>Describe the curves of a file as JSON: kinds, point counts, lengths, bounding boxes, continuity.</source>
        <translation>Opis kriviek súboru v JSON: druhy, počty bodov, dĺžky, ohraničujúce obdĺžniky, spojitosť.</translation>
    </message>
    <message>
        <source>Absolute accuracy of the lengths (default 1e-9).</source>
        <translation>Absolútna presnosť dĺžok (predvolene 1e-9).</translation>
    </message>
    <message>
        <source>--accuracy needs a positive number</source>
        <translation>--accuracy potrebuje kladné číslo</translation>
    </message>
    <message>
        <source>
For every command:
  --lang CODE  the language of help and messages: %1 (default: the system&apos;s)
</source>
        <translation>
Pre všetky príkazy:
  --lang KÓD   jazyk pomocníka a správ: %1 (predvolene jazyk systému)
</translation>
    </message>
    <message>
        <source>kontur-cli: unknown command &quot;%1&quot;</source>
        <translation>kontur-cli: neznámy príkaz „%1“</translation>
    </message>
    <message>
        <source>%1:%2: expected two numbers &quot;x y&quot;, got &quot;%3&quot;</source>
        <translation>%1:%2: očakávané dve čísla „x y“, zadané „%3“</translation>
    </message>
    <message>
        <source>%1: cannot read the file: %2</source>
        <translation>%1: súbor sa nedá prečítať: %2</translation>
    </message>
    <message>
        <source>The family (see above).</source>
        <translation>Rodina (pozri vyššie).</translation>
    </message>
    <message>
        <source>uniform, chord (default) or centripetal.</source>
        <translation>uniform, chord (predvolene) alebo centripetal.</translation>
    </message>
    <message>
        <source>A function spline y(x) over the points&apos; increasing x; --at then takes x values and points are [x, y].</source>
        <translation>Funkčný splajn y(x) nad rastúcimi x bodov; --at potom berie hodnoty x a body sú [x, y].</translation>
    </message>
    <message>
        <source>Start tangent x,y (clamped, global-bspline; default the first chord).</source>
        <translation>Počiatočný smerový vektor x,y (clamped, global-bspline; predvolene prvá tetiva).</translation>
    </message>
    <message>
        <source>End tangent x,y (clamped, global-bspline; default the last chord).</source>
        <translation>Koncový smerový vektor x,y (clamped, global-bspline; predvolene posledná tetiva).</translation>
    </message>
    <message>
        <source>--kind must be one of %1</source>
        <translation>--kind musí byť jeden z: %1</translation>
    </message>
    <message>
        <source>--%1 needs x,y</source>
        <translation>--%1 potrebuje x,y</translation>
    </message>
    <message>
        <source>--order needs an integer</source>
        <translation>--order potrebuje celé číslo</translation>
    </message>
    <message>
        <source>a function B-spline takes a knot vector and control values, not points: drop --function</source>
        <translation>funkčný B-splajn prijíma uzlový vektor a riadiace hodnoty, nie body: vynechajte --function</translation>
    </message>
    <message>
        <source>at least 2 points are needed</source>
        <translation>sú potrebné aspoň 2 body</translation>
    </message>
    <message>
        <source>a vertical or zero end tangent has no slope</source>
        <translation>zvislý alebo nulový koncový smerový vektor nemá smernicu</translation>
    </message>
    <message>
        <source>--knots needs open-uniform, uniform or numbers separated by commas</source>
        <translation>--knots potrebuje open-uniform, uniform alebo čísla oddelené čiarkami</translation>
    </message>
    <message>
        <source>could not compute &quot;%1&quot; as a finite number: the numbers involved exceed the range of double precision</source>
        <translation>„%1“ nemožno vypočítať ako konečné číslo: čísla presahujú rozsah dvojitej presnosti</translation>
    </message>
    <message>
        <source>unknown --solver &quot;%1&quot; (classical or torok)</source>
        <translation>neznámy --solver „%1“ (classical alebo torok)</translation>
    </message>
    <message>
        <source>--solver is for --kind clamped</source>
        <translation>--solver je určený pre --kind clamped</translation>
    </message>
    <message>
        <source>Török&apos;s procedure needs evenly spaced knots: use --param uniform or --function</source>
        <translation>Törökova metóda potrebuje rovnomerne rozložené uzly: použite --param uniform alebo --function</translation>
    </message>
    <message>
        <source>a contour curve is drawn through its points in the plane: drop --function</source>
        <translation>obrysová krivka sa kreslí podľa bodov v rovine: vynechajte --function</translation>
    </message>
    <message>
        <source>--paper needs a4 or letter</source>
        <translation>--paper vyžaduje a4 alebo letter</translation>
    </message>
    <message>
        <source>--orientation needs auto, portrait or landscape</source>
        <translation>--orientation vyžaduje auto, portrait alebo landscape</translation>
    </message>
    <message>
        <source>--overlap needs millimetres from 0 to 50</source>
        <translation>--overlap vyžaduje milimetre od 0 do 50</translation>
    </message>
    <message>
        <source>PDF: the paper, a4 or letter (default a4).</source>
        <translation>PDF: papier, a4 alebo letter (predvolene a4).</translation>
    </message>
    <message>
        <source>PDF: auto (the one with fewer pages), portrait or landscape (default auto).</source>
        <translation>PDF: auto (tá s menším počtom listov), portrait alebo landscape (predvolene auto).</translation>
    </message>
    <message>
        <source>PDF: millimetres neighbouring pages repeat (default 10).</source>
        <translation>PDF: koľko milimetrov susedné listy opakujú (predvolene 10).</translation>
    </message>
    <message>
        <source>Add seam allowances: the offset of each curve (or of curve N) at a distance, written after the
input&apos;s curves. In a .kontur output each allowance keeps its link to its curve.</source>
        <translation>Pridať prídavky na šev: posunutú krivku každej krivky (alebo krivky N) v danej vzdialenosti, zapísanú
za krivky vstupu. Vo výstupe .kontur si každý prídavok zachová prepojenie so svojou krivkou.</translation>
    </message>
    <message>
        <source>Offset only curve N (0-based).</source>
        <translation>Posunúť iba krivku N (od 0).</translation>
    </message>
    <message>
        <source>Distance in the document&apos;s units (default 1 cm).</source>
        <translation>Vzdialenosť v jednotkách dokumentu (predvolene 1 cm).</translation>
    </message>
    <message>
        <source>outside, inside, left or right (default outside).</source>
        <translation>outside, inside, left alebo right (predvolene outside).</translation>
    </message>
    <message>
        <source>Corners: miter, bevel or round (default miter).</source>
        <translation>Rohy: miter, bevel alebo round (predvolene miter).</translation>
    </message>
    <message>
        <source>Longest miter from the corner (default 3 cm).</source>
        <translation>Najväčšia dĺžka ostrého rohu od rohu krivky (predvolene 3 cm).</translation>
    </message>
    <message>
        <source>Largest error of the offset (default 0.05 mm).</source>
        <translation>Najväčšia chyba posunutia (predvolene 0,05 mm).</translation>
    </message>
    <message>
        <source>--distance needs a positive number</source>
        <translation>--distance potrebuje kladné číslo</translation>
    </message>
    <message>
        <source>--miter-limit needs a number of at least 0</source>
        <translation>--miter-limit potrebuje číslo aspoň 0</translation>
    </message>
    <message>
        <source>--tolerance needs a positive number</source>
        <translation>--tolerance potrebuje kladné číslo</translation>
    </message>
    <message>
        <source>unknown --side &quot;%1&quot;</source>
        <translation>neznámy --side „%1“</translation>
    </message>
    <message>
        <source>unknown --join &quot;%1&quot;</source>
        <translation>neznámy --join „%1“</translation>
    </message>
    <message>
        <source>%1: unknown file type (%2)</source>
        <translation>%1: neznámy typ súboru (%2)</translation>
    </message>
    <message>
        <source>Convert between points text (.txt), CSV, Kontur documents (.kontur), SVG and DXF, by extension.
A .txt output is appended to, never overwritten; other outputs are replaced atomically.
A .pdf output prints the visible curves at true size over A4 or Letter pages (a first page with
a 10 cm test square and the overview, then the pages to tape together); the document is kept
inside, so a PDF Kontur wrote converts back.</source>
        <translation>Prevod medzi textom bodov (.txt), CSV, dokumentmi Kontur (.kontur), SVG a DXF podľa prípony.
Výstup .txt sa dopĺňa, nikdy neprepisuje; ostatné výstupy sa nahrádzajú atomicky.
Výstup .pdf vytlačí viditeľné krivky v skutočnej veľkosti na listy A4 alebo Letter (prvý list so
skúšobným štvorcom 10 cm a prehľadom, potom listy na zlepenie); dokument je uložený vnútri, takže PDF
vytvorené programom Kontur sa dá previesť späť.</translation>
    </message>
    <message>
        <source>DXF output: spline (exact Bézier control points, default) or polyline (flattened).</source>
        <translation>Výstup DXF: spline (splajny s presnými riadiacimi bodmi Bézierovej krivky, predvolene) alebo polyline (lomené čiary).</translation>
    </message>
    <message>
        <source>DXF polyline output: largest distance from the curves, in the document&apos;s units (default 0.05 mm).</source>
        <translation>Výstup DXF s lomenými čiarami: najväčšia vzdialenosť od kriviek v jednotkách dokumentu (predvolene 0,05 mm).</translation>
    </message>
    <message>
        <source>unknown --dxf &quot;%1&quot; (spline or polyline)</source>
        <translation>neznámy --dxf „%1“ (spline — splajny, alebo polyline — lomené čiary)</translation>
    </message>
    <message>
        <source>A .txt, .csv, .kontur, .svg or .dxf file.</source>
        <translation>Súbor .txt, .csv, .kontur, .svg alebo .dxf.</translation>
    </message>
    <message>
        <source>The photo (PNG, JPEG, PGM, ...).</source>
        <translation>Fotografia (PNG, JPEG, PGM, ...).</translation>
    </message>
    <message>
        <source>The sheet&apos;s size: a4, a3, letter or WxH with mm (default), cm or in.</source>
        <translation>Veľkosť hárka: a4, a3, letter alebo WxH s mm (predvolene), cm alebo in.</translation>
    </message>
    <message>
        <source>Approximate corners in photo pixels, x,y;x,y;x,y;x,y in any order: the edges are searched near them.</source>
        <translation>Približné rohy v pixeloch fotografie, x,y;x,y;x,y;x,y v ľubovoľnom poradí: hrany sa hľadajú v ich blízkosti.</translation>
    </message>
    <message>
        <source>--sheet needs a4, a3, letter or WxH[mm|cm|in], got &quot;%1&quot;</source>
        <translation>--sheet vyžaduje a4, a3, letter alebo WxH[mm|cm|in], zadané „%1“</translation>
    </message>
    <message>
        <source>--corners needs four points x,y separated by semicolons or spaces</source>
        <translation>--corners vyžaduje štyri body x,y oddelené bodkočiarkami alebo medzerami</translation>
    </message>
    <message>
        <source>%1: cannot read the photo</source>
        <translation>%1: fotografiu nemožno prečítať</translation>
    </message>
    <message>
        <source>Trace a pattern photographed beside a reference sheet: the sheet is found (its corners to a
fraction of a pixel), the photo rectified into the sheet&apos;s plane and every pattern piece&apos;s outline
written as a closed composite curve in mm to OUT.kontur, with the photo as its calibrated
background. --json prints the corners, the calibration&apos;s estimated error and each curve&apos;s knots.</source>
        <translation>Obkresliť strih odfotografovaný vedľa referenčného hárka: hárok sa nájde (jeho rohy s presnosťou
na zlomok pixela), fotografia sa narovná do roviny hárka a obrys každého dielu strihu sa zapíše
do OUT.kontur ako uzavretá zložená krivka v mm, s fotografiou ako kalibrovaným obrázkom na pozadí.
--json vypíše rohy, odhadovanú chybu kalibrácie a uzly každej krivky.</translation>
    </message>
    <message>
        <source>The document to write (.kontur).</source>
        <translation>Dokument, ktorý sa zapíše (.kontur).</translation>
    </message>
    <message>
        <source>Print the sheet&apos;s corners, the calibration error and the outlines&apos; knots as JSON.</source>
        <translation>Vypísať rohy hárka, chybu kalibrácie a uzly obrysov ako JSON.</translation>
    </message>
    <message>
        <source>trace needs an output file OUT.kontur, or --json for the sheet&apos;s corners</source>
        <translation>na obkreslenie (trace) treba výstupný súbor OUT.kontur alebo --json pre rohy hárka</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1: curve %2: %3</source>
        <translation>%1: krivka %2: %3</translation>
    </message>
    <message>
        <source>no such file</source>
        <translation>taký súbor neexistuje</translation>
    </message>
    <message>
        <source>its symbolic links form a loop</source>
        <translation>jeho symbolické odkazy tvoria slučku</translation>
    </message>
    <message>
        <source>permission denied</source>
        <translation>prístup zamietnutý</translation>
    </message>
    <message>
        <source>it is a folder, not a file</source>
        <translation>je to priečinok, nie súbor</translation>
    </message>
    <message>
        <source>it is a named pipe (FIFO), not a regular file</source>
        <translation>je to pomenovaná rúra (FIFO), nie bežný súbor</translation>
    </message>
    <message>
        <source>it is a device, not a regular file</source>
        <translation>je to zariadenie, nie bežný súbor</translation>
    </message>
    <message>
        <source>it is not a regular file</source>
        <translation>nie je to bežný súbor</translation>
    </message>
    <message>
        <source>%1: a CSV file holds the points of one curve; the input has %2: choose one with --curve N</source>
        <translation>%1: súbor CSV obsahuje body jednej krivky; vstup má %2: vyberte jednu pomocou --curve N</translation>
    </message>
    <message>
        <source>%1: unknown language &quot;%2&quot;; choose one of: %3.</source>
        <extracomment>%1 is the program (kontur or kontur-cli), %2 the language code asked for, %3 the codes there are.</extracomment>
        <translation>%1: neznámy jazyk „%2“; vyberte jeden z: %3.</translation>
    </message>
    <message>
        <source>Rounds of parameter correction (default 0: the parameters are used as computed).</source>
        <translation>Počet krokov korekcie parametrov (predvolene 0: parametre sa použijú tak, ako boli vypočítané).</translation>
    </message>
    <message>
        <source>%1: %2 points; a least-squares cubic needs at least 4</source>
        <translation>%1: počet bodov %2; kubická krivka metódou najmenších štvorcov potrebuje aspoň 4</translation>
    </message>
    <message>
        <source>Work with the Bézier curve whose control points are in the file. Prints the control points (JSON key control_points) when --elevate is given or when nothing else is asked for.</source>
        <translation>Práca s Bézierovou krivkou, ktorej kontrolné body sú v súbore. Vypíše kontrolné body (kľúč JSON control_points), ak je zadané --elevate alebo ak sa nič iné nežiada.</translation>
    </message>
    <message>
        <source>%1: %2 points; a Bézier curve needs at least 2</source>
        <extracomment>%1 is a file name, %2 the number of points in it.</extracomment>
        <translation>%1: počet bodov %2; Bézierova krivka potrebuje aspoň 2</translation>
    </message>
    <message>
        <source>%1: %2 points; a closed composite curve needs at least 3</source>
        <extracomment>%1 is a file name, %2 the number of points in it.</extracomment>
        <translation>%1: počet bodov %2; uzavretá zložená krivka potrebuje aspoň 3</translation>
    </message>
    <message>
        <source>%1: %2 points; a composite curve needs at least 2</source>
        <translation>%1: počet bodov %2; zložená krivka potrebuje aspoň 2</translation>
    </message>
    <message>
        <source>clamped on evenly spaced knots (--function over evenly spaced x, or --param uniform): classical (default, k - 2 unknowns) or torok (Török&apos;s half-size system); prints the JSON key &quot;solverDifference&quot;: the largest difference of the derivatives from the other solver.</source>
        <translation>clamped na rovnomerne rozložených uzloch (--function nad rovnomerne rozloženými x alebo --param uniform): classical (predvolene, k - 2 neznámych) alebo torok (Törökova sústava polovičnej veľkosti); vypíše kľúč JSON &quot;solverDifference&quot;: najväčší rozdiel derivácií od druhej metódy.</translation>
    </message>
    <message>
        <source>Evaluate at u1,u2,… (a negative first value needs the = form: --at=-1,0.5).</source>
        <translation>Vyhodnotiť v bodoch u1, u2, … (zápornú prvú hodnotu píšte s =: --at=-1,0.5).</translation>
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
        <translation>Použitie: kontur-cli &lt;príkaz&gt; [voľby]   (kontur-cli &lt;príkaz&gt; --help ukáže jeho voľby)
Nástroj Kontur pre príkazový riadok: Bézierove krivky a splajny bez okna.

Príkazy:
  fit        kubická krivka cez 4 body alebo kubická krivka metódou najmenších štvorcov cez n &gt;= 4 body
  bezier     vyhodnotenie, zvýšenie stupňa, meranie a dopyty Bézierovej krivky ľubovoľného stupňa
  composite  zložená krivka cez uzly so správou o spojitosti
  spline     krivka ľubovoľného druhu cez body, zostrojená ako v aplikácii (bezier,
             composite, natural, clamped, hermite, bspline, function-spline, contour, …)
  convert    prevod IN OUT medzi textom bodov (.txt), CSV, .kontur, SVG, DXF a PDF (podľa prípony;
             výstup PDF je strih vytlačený v skutočnej veľkosti)
  info       krivky súboru v JSON: druhy, dĺžky, ohraničujúci obdĺžnik, spojitosť
  offset     prídavky na šev: posunuté krivky IN OUT v danej vzdialenosti, zvonka alebo zvnútra
  trace      obkresliť strih odfotografovaný vedľa referenčného hárka do dokumentu v mm
  bench      zmeranie času operácie geometrického jadra (pre vývojárov)

Vstupné súbory majú jednu dvojicu „x y“ na riadok; „#“ začína komentár. Výstup je JSON na stdout;
chyby idú na stderr s návratovým kódom 1 (chybný vstup) alebo 2 (chybné použitie).
</translation>
    </message>
    <message>
        <source>The curve of a kind through the points of a file (one &quot;x y&quot; per line), built by the same function as the app&apos;s curve of that kind: bezier (the points are its control points), interpolating, least-squares, composite, natural, clamped, not-a-knot, periodic, catmull-rom, hermite, bspline (the points are its control polygon), global-bspline, polynomial, function-spline (the natural spline y(x)) or contour (Bézier pieces joined at the midpoints of pairs of points). Prints {&quot;knots&quot;: parameter of each point (the knot vector for bspline; 0, 1, … one per piece for bezier, interpolating, least-squares, composite and contour), &quot;segments&quot;: Bézier control points of each piece, &quot;points&quot;: [u, x, y] at --at}. Parameters are unnormalised: uniform 0, 1, 2, …; chord the cumulative chord length; centripetal the cumulative square roots.</source>
        <translation>Krivka daného druhu cez body súboru (jedno „x y“ na riadok), zostrojená tou istou funkciou ako krivka tohto druhu v aplikácii: bezier (body sú jej kontrolné body), interpolating, least-squares, composite, natural, clamped, not-a-knot, periodic, catmull-rom, hermite, bspline (body sú jeho riadiaci polygón), global-bspline, polynomial, function-spline (prirodzený splajn y(x)) alebo contour (Bézierove úseky spojené v stredoch dvojíc bodov). Vypíše {&quot;knots&quot;: parameter každého bodu (pre bspline uzlový vektor; pre bezier, interpolating, least-squares, composite a contour 0, 1, …, jeden na úsek), &quot;segments&quot;: Bézierove kontrolné body každého úseku, &quot;points&quot;: [u, x, y] v --at}. Parametre nie sú normované: uniform 0, 1, 2, …; chord kumulatívna dĺžka tetív; centripetal kumulatívne odmocniny.</translation>
    </message>
    <message>
        <source>B-spline order k, 2 to 10 (default as in the app: 4, cubic, or the number of points when fewer).</source>
        <translation>Rád B-splajnu k, od 2 do 10 (predvolene ako v aplikácii: 4, kubický, alebo počet bodov, ak ich je menej).</translation>
    </message>
    <message>
        <source>B-spline knot vector: open-uniform (default, the app&apos;s knots), uniform, or u0,u1,… (n + k values).</source>
        <translation>Uzlový vektor B-splajnu: open-uniform (predvolene, uzly aplikácie), uniform alebo u0,u1,… (n + k hodnôt).</translation>
    </message>
    <message>
        <source>hermite: a file with one tangent &quot;x y&quot; per point (default Catmull–Rom tangents, as in the app).</source>
        <translation>hermite: súbor s jedným smerovým vektorom „x y“ pre každý bod (predvolene smerové vektory Catmull–Rom ako v aplikácii).</translation>
    </message>
    <message>
        <source>composite: the closed curve (as Close curve makes it in the app).</source>
        <translation>composite: uzavretá krivka (ako ju v aplikácii vytvorí „Uzavrieť krivku“).</translation>
    </message>
    <message>
        <source>--closed is for --kind composite (the periodic spline is closed by its kind)</source>
        <translation>--closed je pre --kind composite (periodický splajn je uzavretý svojím druhom)</translation>
    </message>
    <message>
        <source>%1: not drawn: %2</source>
        <translation>%1: nenakreslené: %2</translation>
    </message>
    <message>
        <source>Units of a DXF that names none: mm, cm, in or px (default px).</source>
        <translation>Jednotky DXF, ktorý ich neuvádza: mm, cm, in alebo px (predvolene px).</translation>
    </message>
    <message>
        <source>--units needs mm, cm, in or px</source>
        <translation>--units potrebuje mm, cm, in alebo px</translation>
    </message>
    <message>
        <source>DXF output as ASTM D6673 (AAMA) garment pieces: a block per closed curve, its cut line (its seam allowance, if any) and texts on layer 1, sew line 14, notches 4, mirror line 6, the piece&apos;s own grain line 7 (none if it has none), internal lines 8, drill holes 13; polylines unless --dxf spline is given.</source>
        <translation>Výstup DXF ako odevné diely podľa ASTM D6673 (AAMA): blok pre každú uzavretú krivku, jej strihová čiara (prídavok na šev, ak ho má) a texty vo vrstve 1, čiara šva 14, zárezy 4, čiara lomu (zrkadlenia) 6, vlastná čiara osnovy dielu 7 (žiadna, ak ju diel nemá), vnútorné čiary 8, vrtané otvory 13; lomené čiary, ak nie je dané --dxf spline (splajny).</translation>
    </message>
    <message>
        <source>%1: the sheet is not flat (its edges are not straight); lay it flat and photograph it again, or give its four corners roughly with --corners x,y;x,y;x,y;x,y</source>
        <translation>%1: hárok nie je rovný (jeho okraje nie sú rovné); položte ho naplocho a znova ho odfotografujte alebo zadajte jeho štyri rohy približne pomocou --corners x,y;x,y;x,y;x,y</translation>
    </message>
    <message>
        <source>%1: the rectangle found is about %2 : 1, not %3 (%4 : 1); give the sheet&apos;s size with --sheet, or its four corners roughly with --corners x,y;x,y;x,y;x,y</source>
        <extracomment>%2 and %4 are proportions such as 2.35 and 1.41 (long side : short side), %3 the sheet&apos;s size as given.</extracomment>
        <translation>%1: nájdený obdĺžnik má pomer strán asi %2 : 1, nie %3 (%4 : 1); zadajte veľkosť hárka pomocou --sheet alebo jeho štyri rohy približne pomocou --corners x,y;x,y;x,y;x,y</translation>
    </message>
    <message>
        <source>%1: no reference sheet found (a white rectangle with four straight, clear edges); give its four corners roughly with --corners x,y;x,y;x,y;x,y</source>
        <translation>%1: referenčný hárok sa nenašiel (biely obdĺžnik so štyrmi rovnými, zreteľnými okrajmi); zadajte jeho štyri rohy približne pomocou --corners x,y;x,y;x,y;x,y</translation>
    </message>
    <message>
        <source>%1: no pattern piece found beside the sheet; nothing was written (the sheet was found)</source>
        <translation>%1: vedľa hárka sa nenašiel žiadny diel strihu; nič sa nezapísalo (hárok sa našiel)</translation>
    </message>
    <message>
        <source>%1: no grain line written for pieces without a grainline: %2</source>
        <translation>%1: pre diely bez smeru osnovy nebola zapísaná čiara smeru osnovy: %2</translation>
    </message>
</context>
<context>
    <name>kontur::print</name>
    <message>
        <source>Print at 100 % (actual size, not “fit to page”). The grey square must measure 10 cm each way.</source>
        <translation>Tlačte v mierke 100 % (skutočná veľkosť, nie „prispôsobiť stránke“). Sivý štvorec musí merať 10 cm na každú stranu.</translation>
    </message>
    <message>
        <source>landscape</source>
        <extracomment>Page orientation, inserted after the paper name in the sentence above (A4 landscape).</extracomment>
        <translation>na šírku</translation>
    </message>
    <message>
        <source>portrait</source>
        <translation>na výšku</translation>
    </message>
    <message>
        <source>Cut each page along the grey line at its left and top, lay it over its neighbours up to their dashed lines, match the circles and tape.</source>
        <translation>Každý list odstrihnite vľavo a hore pozdĺž sivej čiary, položte ho na susedné listy po ich prerušované čiary, zarovnajte krúžky a zlepte.</translation>
    </message>
    <message>
        <source>The drawing is in px: printed at 96 px per inch.</source>
        <translation>Kresba je v pixeloch (px): vytlačená so 96 px na palec.</translation>
    </message>
    <message>
        <source>10 cm</source>
        <translation>10 cm</translation>
    </message>
    <message>
        <source>4 in</source>
        <translation>4 palce</translation>
    </message>
    <message>
        <source>Pages after this one: %1 (rows × columns: %2 × %3), %4 %5, overlap %6 mm.</source>
        <extracomment>%1 is the number of pages, %2 × %3 their rows and columns, %4 the paper (A4 or Letter), %5 the orientation (“portrait” or “landscape”, the next messages), %6 a number of millimetres.</extracomment>
        <translation>Ďalšie listy: %1 (riadky × stĺpce: %2 × %3), %4 %5, prekrytie %6 mm.</translation>
    </message>
    <message>
        <source>Place on fold</source>
        <extracomment>Printed along a pattern piece&apos;s fold line: the piece is laid with this edge on the fabric&apos;s fold.</extracomment>
        <translation>Položiť na lom</translation>
    </message>
    <message>
        <source>Size %1</source>
        <extracomment>A pattern piece&apos;s size on the printed pattern (a garment size such as 38 or M).</extracomment>
        <translation>Veľkosť %1</translation>
    </message>
    <message numerus="yes">
        <source>Cut %n on fold</source>
        <extracomment>How many pieces to cut, printed on the pattern piece; the piece lies on the fabric&apos;s fold.</extracomment>
        <translation>
            <numerusform>Strihať %n× na lom</numerusform>
            <numerusform>Strihať %n× na lom</numerusform>
            <numerusform>Strihať %n× na lom</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Cut %n</source>
        <extracomment>How many pieces to cut, printed on the pattern piece (&quot;Cut 2&quot;).</extracomment>
        <translation>
            <numerusform>Strihať %n×</numerusform>
            <numerusform>Strihať %n×</numerusform>
            <numerusform>Strihať %n×</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 in</source>
        <extracomment>A seam&apos;s allowance width printed beside it on the pattern, in inches.</extracomment>
        <translation>%1 palca</translation>
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
        <translation>Chcete všetko vymazať? Všetky krivky budú odstránené.</translation>
    </message>
    <message>
        <source>“%1” is locked: unlock it to change it.</source>
        <translation>Krivka „%1“ je zamknutá: ak ju chcete zmeniť, odomknite ju.</translation>
    </message>
    <message>
        <source>Could not read “%1”: %2</source>
        <translation>Nepodarilo sa prečítať súbor „%1“: %2</translation>
    </message>
    <message numerus="yes">
        <source>%n curve(s) read from “%1”.</source>
        <translation>
            <numerusform>Zo súboru „%1“ bola načítaná %n krivka.</numerusform>
            <numerusform>Zo súboru „%1“ boli načítané %n krivky.</numerusform>
            <numerusform>Zo súboru „%1“ bolo načítaných %n kriviek.</numerusform>
        </translation>
    </message>
    <message>
        <source>Saved “%1”.</source>
        <translation>Súbor „%1“ bol uložený.</translation>
    </message>
    <message>
        <source>This knot lies on the first knot of the closed curve, which joins them already. Nothing was changed.</source>
        <translation>Tento uzol splýva s prvým uzlom uzavretej krivky, ktorá ich už spája. Nič sa nezmenilo.</translation>
    </message>
    <message>
        <source>This seam allowance follows its curve: change the curve or the allowance&apos;s settings, or detach the allowance to edit it.</source>
        <translation>Tento prídavok na šev sleduje svoju krivku: zmeňte krivku alebo nastavenia prídavku, alebo prídavok odpojte, ak ho chcete upravovať.</translation>
    </message>
    <message>
        <source>No seam allowance of this width fits the curve on that side.</source>
        <translation>Prídavok na šev tejto šírky sa na tej strane do krivky nezmestí.</translation>
    </message>
    <message>
        <source>This width is more than %1 times the size of the curve: no seam allowance is made of it. Nothing was changed.</source>
        <translation>Táto šírka je viac ako %1-násobok veľkosti krivky: taký prídavok na šev sa nevytvára. Nič sa nezmenilo.</translation>
    </message>
    <message>
        <source>This seam allowance would need too many pieces at this size. Nothing was changed.</source>
        <translation>Tento prídavok na šev by pri tejto veľkosti potreboval príliš veľa segmentov. Nič sa nezmenilo.</translation>
    </message>
    <message>
        <source>The seam allowance “%1” keeps the shape it was saved with: its width %2 gives no allowance of its curve.</source>
        <translation>Prídavok na šev „%1“ si ponecháva tvar, s ktorým bol uložený: jeho šírka %2 nedáva žiadny prídavok jeho krivky.</translation>
    </message>
    <message numerus="yes">
        <source>The autosave setting “%1” cannot be used: a recovery copy is saved every %n second(s).</source>
        <translation>
            <numerusform>Nastavenie automatického ukladania „%1“ nemožno použiť: záložná kópia sa ukladá každú %n sekundu.</numerusform>
            <numerusform>Nastavenie automatického ukladania „%1“ nemožno použiť: záložná kópia sa ukladá každé %n sekundy.</numerusform>
            <numerusform>Nastavenie automatického ukladania „%1“ nemožno použiť: záložná kópia sa ukladá každých %n sekúnd.</numerusform>
        </translation>
    </message>
    <message>
        <source>The background image “%1” is missing or cannot be read. The curves are shown without it.</source>
        <translation>Obrázok na pozadí „%1“ chýba alebo sa nedá prečítať. Krivky sa zobrazujú bez neho.</translation>
    </message>
    <message>
        <source>The picture “%1” could not be loaded: the file is missing or is not a picture Kontur can read.</source>
        <extracomment>%1 is a file name. The background picture could not be loaded.</extracomment>
        <translation>Obrázok „%1“ sa nepodarilo načítať: súbor chýba alebo nie je obrázok, ktorý Kontur dokáže prečítať.</translation>
    </message>
    <message>
        <source>The .txt file is not in the expected format: one “x y” pair per line.</source>
        <translation>Súbor .txt nemá očakávaný formát: na každom riadku má byť jedna dvojica „x y“.</translation>
    </message>
    <message>
        <source>Could not append to “%1”: %2</source>
        <extracomment>%1 is a file name, %2 the reason (from the system). The curve&apos;s points are appended to a .txt file.</extracomment>
        <translation>Do „%1“ sa nepodarilo pripísať: %2</translation>
    </message>
    <message>
        <source>The control points of curves of the kind “%1” cannot be moved: move the knots.</source>
        <extracomment>%1 is the name of a curve kind, as in the kind menu (&quot;Natural spline&quot;, &quot;Composite curve&quot;).</extracomment>
        <translation>Kontrolné body kriviek druhu „%1“ sa nedajú posúvať: posúvajte uzly.</translation>
    </message>
    <message>
        <source>The control points of a composite curve cannot be moved by keyboard: drag them.</source>
        <translation>Kontrolné body zloženej krivky sa nedajú posúvať klávesnicou: ťahajte ich.</translation>
    </message>
    <message>
        <source>Curves of the kind “%1” do not use a parameterization.</source>
        <extracomment>%1 is the name of a curve kind, as in the kind menu (&quot;Bézier curve&quot;, &quot;Natural spline&quot;).</extracomment>
        <translation>Krivky druhu „%1“ nepoužívajú parametrizáciu.</translation>
    </message>
    <message>
        <source>Too many points: a curve of this kind can have at most %1.</source>
        <extracomment>%1 is the largest number of points a curve of this kind can have (for example 1 000).</extracomment>
        <translation>Príliš veľa bodov: krivka tohto druhu môže mať najviac %1.</translation>
    </message>
    <message>
        <source>A curve of the kind “%1” needs at least %2 points.</source>
        <extracomment>%1 is the name of a curve kind, as in the kind menu (&quot;Bézier curve&quot;); %2 is a small number (2 to 4).</extracomment>
        <translation>Krivka druhu „%1“ potrebuje aspoň %2 body.</translation>
    </message>
    <message>
        <source>Some values are missing or are not numbers: fill in every field with a number.</source>
        <translation>Niektoré hodnoty chýbajú alebo nie sú čísla: do každého poľa zadajte číslo.</translation>
    </message>
    <message>
        <source>The knots of this curve (kind “%1”) do not define a curve: they need at least 4 different positions.</source>
        <extracomment>%1 is the name of a curve kind, as in the kind menu (&quot;Least-squares cubic&quot;).</extracomment>
        <translation>Uzly tejto krivky (druh „%1“) neurčujú krivku: potrebujú aspoň 4 rôzne polohy.</translation>
    </message>
    <message>
        <source>Too large: the coordinates would exceed the largest number Kontur can hold (about %1). Nothing was changed.</source>
        <translation>Príliš veľká hodnota: súradnice by prekročili najväčšie číslo, ktoré Kontur dokáže uchovať (približne %1). Nič sa nezmenilo.</translation>
    </message>
    <message>
        <source>This is not possible for curves of the kind “%1”.</source>
        <extracomment>%1 is the name of a curve kind, as in the kind menu (&quot;Bézier curve&quot;, &quot;Global B-spline&quot;).</extracomment>
        <translation>Pri krivkách druhu „%1“ to nie je možné.</translation>
    </message>
    <message>
        <source>A seam allowance is still being computed: wait for it or cancel it first.</source>
        <translation>Prídavok na šev sa ešte počíta: počkajte naň alebo ho najprv zrušte.</translation>
    </message>
    <message>
        <source>The seam allowance was cancelled. Nothing was changed.</source>
        <translation>Prídavok na šev bol zrušený. Nič sa nezmenilo.</translation>
    </message>
    <message>
        <source>The curve changed while its seam allowance was computed. Nothing was changed; add or apply it again.</source>
        <translation>Krivka sa zmenila, kým sa počítal jej prídavok na šev. Nič sa nezmenilo; pridajte ho alebo ho použite znova.</translation>
    </message>
    <message numerus="yes">
        <source>%n text(s)</source>
        <translation>
            <numerusform>%n text</numerusform>
            <numerusform>%n texty</numerusform>
            <numerusform>%n textov</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n dimension(s)</source>
        <translation>
            <numerusform>%n kóta</numerusform>
            <numerusform>%n kóty</numerusform>
            <numerusform>%n kót</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n 3D object(s)</source>
        <translation>
            <numerusform>%n 3D objekt</numerusform>
            <numerusform>%n 3D objekty</numerusform>
            <numerusform>%n 3D objektov</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n image(s)</source>
        <translation>
            <numerusform>%n obrázok</numerusform>
            <numerusform>%n obrázky</numerusform>
            <numerusform>%n obrázkov</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n spline(s) given only by fit points or weights</source>
        <translation>
            <numerusform>%n splajn daný len bodmi preloženia alebo váhami</numerusform>
            <numerusform>%n splajny dané len bodmi preloženia alebo váhami</numerusform>
            <numerusform>%n splajnov daných len bodmi preloženia alebo váhami</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n other object(s)</source>
        <translation>
            <numerusform>%n iný objekt</numerusform>
            <numerusform>%n iné objekty</numerusform>
            <numerusform>%n iných objektov</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n curve(s) read from “%1”; not drawn: %2.</source>
        <translation>
            <numerusform>Zo súboru „%1“ bola načítaná %n krivka; nenakreslené: %2.</numerusform>
            <numerusform>Zo súboru „%1“ boli načítané %n krivky; nenakreslené: %2.</numerusform>
            <numerusform>Zo súboru „%1“ bolo načítaných %n kriviek; nenakreslené: %2.</numerusform>
        </translation>
    </message>
    <message>
        <source>Could not write “%1”: %2 The file was left as it was.</source>
        <translation>Nepodarilo sa zapísať súbor „%1“: %2 Súbor zostal nezmenený.</translation>
    </message>
    <message numerus="yes">
        <source>%n curve(s) read from “%1”, which does not say its units: read in %2, as chosen for such files.</source>
        <extracomment>%1 is a file name, %2 a unit (mm, cm, in or px) the user chose once for DXF files without units.</extracomment>
        <translation>
            <numerusform>Zo súboru „%1“, ktorý neuvádza svoje jednotky, bola načítaná %n krivka: v jednotkách %2, ako bolo zvolené pre takéto súbory.</numerusform>
            <numerusform>Zo súboru „%1“, ktorý neuvádza svoje jednotky, boli načítané %n krivky: v jednotkách %2, ako bolo zvolené pre takéto súbory.</numerusform>
            <numerusform>Zo súboru „%1“, ktorý neuvádza svoje jednotky, bolo načítaných %n kriviek: v jednotkách %2, ako bolo zvolené pre takéto súbory.</numerusform>
        </translation>
    </message>
    <message>
        <source>Not drawn: %1.</source>
        <extracomment>Appended to the message that curves were read from a file; %1 lists what was not drawn.</extracomment>
        <translation>Nenakreslené: %1.</translation>
    </message>
    <message>
        <source>DXF files that do not say their units are read in %1 from the next import on.</source>
        <extracomment>%1 is a unit (mm, cm, in or px).</extracomment>
        <translation>Súbory DXF, ktoré neuvádzajú svoje jednotky, sa od ďalšieho importu čítajú v jednotkách %1.</translation>
    </message>
    <message>
        <source>Nothing was exported: pattern software takes each piece as a closed curve, and this document has no visible closed curve. Close the outline of each piece first.</source>
        <extracomment>AAMA (ASTM D6673) is the DXF that garment pattern software reads; a piece is a garment pattern piece.</extracomment>
        <translation>Nič sa neexportovalo: programy na strihy berú každý diel ako uzavretú krivku a tento dokument nemá žiadnu viditeľnú uzavretú krivku. Najprv uzavrite obrys každého dielu.</translation>
    </message>
    <message>
        <source>Seam allowance of %2 added to “%1”. To change it, select it and choose Seam allowance again.</source>
        <extracomment>%1 is the curve&apos;s name, %2 the width with its unit (10.00 mm).</extracomment>
        <translation>Pre krivku „%1“ bol vytvorený prídavok na šev %2. Ak ho chcete zmeniť, vyberte ho a znova zvoľte „Prídavok na šev“.</translation>
    </message>
    <message numerus="yes">
        <source>“%1” traced with %n knot(s). For the next piece, choose Trace outline again.</source>
        <extracomment>%1 is the new curve&apos;s name; Trace outline is the command in the Trace menu.</extracomment>
        <translation>
            <numerusform>Krivka „%1“ bola obkreslená s %n uzlom. Pre ďalší diel znova zvoľte „Obkresliť obrys“.</numerusform>
            <numerusform>Krivka „%1“ bola obkreslená s %n uzlami. Pre ďalší diel znova zvoľte „Obkresliť obrys“.</numerusform>
            <numerusform>Krivka „%1“ bola obkreslená s %n uzlami. Pre ďalší diel znova zvoľte „Obkresliť obrys“.</numerusform>
        </translation>
    </message>
    <message>
        <source>the grainline</source>
        <extracomment>One of the marks found on a traced pattern piece, listed after the curve&apos;s name.</extracomment>
        <translation>smer osnovy</translation>
    </message>
    <message>
        <source>the fold line</source>
        <extracomment>One of the marks found on a traced pattern piece: the edge laid on the fabric&apos;s fold.</extracomment>
        <translation>čiara lomu</translation>
    </message>
    <message numerus="yes">
        <source>%n notch(es)</source>
        <extracomment>One of the marks found on a traced pattern piece (V or slit cuts in its edge).</extracomment>
        <translation>
            <numerusform>%n zárez</numerusform>
            <numerusform>%n zárezy</numerusform>
            <numerusform>%n zárezov</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n drill hole(s)</source>
        <extracomment>One of the marks found on a traced pattern piece.</extracomment>
        <translation>
            <numerusform>%n vrtaný otvor</numerusform>
            <numerusform>%n vrtané otvory</numerusform>
            <numerusform>%n vrtaných otvorov</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>“%1” traced with %n knot(s) as a pattern piece with %2. Check them under Pattern piece; for the next piece, choose Trace outline again.</source>
        <extracomment>%1 is the new curve&apos;s name, %2 the marks found on it (&quot;the grainline, 3 notches, 1 drill hole&quot;); Pattern piece is the command that opens the piece bar; Trace outline the command in the Trace menu.</extracomment>
        <translation>
            <numerusform>Krivka „%1“ bola obkreslená s %n uzlom ako strihový diel; nájdené značky: %2. Skontrolujte ich v „Strihový diel“; pre ďalší diel znova zvoľte „Obkresliť obrys“.</numerusform>
            <numerusform>Krivka „%1“ bola obkreslená s %n uzlami ako strihový diel; nájdené značky: %2. Skontrolujte ich v „Strihový diel“; pre ďalší diel znova zvoľte „Obkresliť obrys“.</numerusform>
            <numerusform>Krivka „%1“ bola obkreslená s %n uzlami ako strihový diel; nájdené značky: %2. Skontrolujte ich v „Strihový diel“; pre ďalší diel znova zvoľte „Obkresliť obrys“.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>“%1” was written, but %n piece(s) without a grainline have no grain line in it: %2. Marker making cannot lay them on grain; draw each piece&apos;s grainline.</source>
        <extracomment>%1 is the file, %2 the pieces&apos; names; the grainline is the pattern piece&apos;s straight-of-grain line.</extracomment>
        <translation>
            <numerusform>„%1“ bol zapísaný, ale %n diel bez smeru osnovy v ňom nemá čiaru smeru osnovy: %2. Pri kladení strihu ho nemožno položiť v smere osnovy; nakreslite každému dielu smer osnovy.</numerusform>
            <numerusform>„%1“ bol zapísaný, ale %n diely bez smeru osnovy v ňom nemajú čiaru smeru osnovy: %2. Pri kladení strihu ich nemožno položiť v smere osnovy; nakreslite každému dielu smer osnovy.</numerusform>
            <numerusform>„%1“ bol zapísaný, ale %n dielov bez smeru osnovy v ňom nemá čiaru smeru osnovy: %2. Pri kladení strihu ich nemožno položiť v smere osnovy; nakreslite každému dielu smer osnovy.</numerusform>
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
        <translation>%1 palca</translation>
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
        <translation>palce</translation>
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
