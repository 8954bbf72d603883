<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="sk">
<context>
    <name>CanvasView</name>
    <message>
        <source>grid %1</source>
        <translation>mriežka %1</translation>
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
        <translation>Obnoviť</translation>
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
        <translation>Kopírovať</translation>
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
        <source>Press “New Bézier” and tap 4 points to draw your first curve.</source>
        <translation>Stlačte „Nová Bézierova krivka“ a ťuknutím zadajte 4 body svojej prvej krivky.</translation>
    </message>
    <message>
        <source>Drag a point to move it. Drag the canvas to pan; pinch or scroll to zoom.</source>
        <translation>Ťahaním bod posuniete. Ťahaním plátna posúvate pohľad; priblížite roztiahnutím dvoch prstov alebo kolieskom myši.</translation>
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
        <translation>Hotovo</translation>
    </message>
    <message>
        <source>Finish the curve with the points placed so far (Enter)</source>
        <translation>Dokončiť krivku s doteraz umiestnenými bodmi (Enter)</translation>
    </message>
    <message>
        <source>Constrained</source>
        <translation>Obmedzene</translation>
    </message>
    <message>
        <source>Composite handles keep their direction and change only their length (or drag with the right button or Shift)</source>
        <translation>Úchyty zloženej krivky si zachovajú smer a menia len dĺžku (alebo ťahajte pravým tlačidlom či so Shift)</translation>
    </message>
    <message>
        <source>New curve: tap or click its points (%1 placed). Press Done to finish, Esc to cancel.</source>
        <translation>Nová krivka: ťuknite alebo kliknite na jej body (umiestnené: %1). Stlačte Hotovo na dokončenie, Esc na zrušenie.</translation>
    </message>
    <message>
        <source>New curve: tap or click point %1 of %2. Esc cancels.</source>
        <translation>Nová krivka: ťuknite alebo kliknite a umiestnite bod %1 z %2. Esc zruší.</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Súbor</translation>
    </message>
    <message>
        <source>New</source>
        <translation>Nový</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Otvoriť…</translation>
    </message>
    <message>
        <source>Open recent</source>
        <translation>Otvoriť nedávne</translation>
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
        <source>Import points, CSV or SVG…</source>
        <translation>Importovať body, CSV alebo SVG…</translation>
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
        <source>Grid</source>
        <translation>Mriežka</translation>
    </message>
    <message>
        <source>Show or hide the grid and the axes (G)</source>
        <translation>Zobraziť alebo skryť mriežku a osi (G)</translation>
    </message>
    <message>
        <source>Reset all</source>
        <translation>Obnoviť všetko</translation>
    </message>
    <message>
        <source>Close message</source>
        <translation>Zavrieť správu</translation>
    </message>
    <message>
        <source>Kontur documents (*.kontur)</source>
        <translation>Dokumenty Kontur (*.kontur)</translation>
    </message>
    <message>
        <source>Points, CSV and SVG files (*.txt *.csv *.svg)</source>
        <translation>Súbory bodov, CSV a SVG (*.txt *.csv *.svg)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Všetky súbory (*)</translation>
    </message>
    <message>
        <source>Open</source>
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
        <source>Points, CSV, SVG and Kontur files (*.txt *.csv *.svg *.kontur)</source>
        <translation>Súbory bodov, CSV, SVG a Kontur (*.txt *.csv *.svg *.kontur)</translation>
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
        <source>Unsaved changes</source>
        <translation>Neuložené zmeny</translation>
    </message>
    <message>
        <source>“%1” has changes that are not saved. Save them first?</source>
        <translation>Dokument „%1“ má neuložené zmeny. Chcete ich najprv uložiť?</translation>
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
        <source>Load background image</source>
        <translation>Načítať obrázok na pozadí</translation>
    </message>
    <message>
        <source>Images (*.png *.jpg *.jpeg *.bmp *.gif *.webp)</source>
        <translation>Obrázky (*.png *.jpg *.jpeg *.bmp *.gif *.webp)</translation>
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
        <translation>Rovnomerná</translation>
    </message>
    <message>
        <source>Chord length</source>
        <translation>Dĺžka tetív</translation>
    </message>
    <message>
        <source>Centripetal</source>
        <translation>Centripetálna</translation>
    </message>
    <message>
        <source>Order</source>
        <translation>Rád splajnu</translation>
    </message>
    <message>
        <source>Node type</source>
        <translation>Typ uzla</translation>
    </message>
    <message>
        <source>Smooth</source>
        <translation>Hladký</translation>
    </message>
    <message>
        <source>Symmetric</source>
        <translation>Symetrický</translation>
    </message>
    <message>
        <source>Corner</source>
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
        <source>Delete %1</source>
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
        <translation>Cez 4 body %1</translation>
    </message>
    <message>
        <source>Least squares %1</source>
        <translation>Najmenšie štvorce %1</translation>
    </message>
    <message>
        <source>Composite %1</source>
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
        <translation>Obnoviť všetko</translation>
    </message>
    <message>
        <source>Natural spline</source>
        <translation>Prirodzený splajn</translation>
    </message>
    <message>
        <source>Clamped spline</source>
        <translation>Vnorený splajn</translation>
    </message>
    <message>
        <source>Not-a-knot spline</source>
        <translation>Splajn s podmienkou not-a-knot</translation>
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
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>Change order</source>
        <translation>Zmeniť rád splajnu</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Bez názvu</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Importovať %1</translation>
    </message>
</context>
<context>
    <name>messages</name>
    <message>
        <source>File upload error!</source>
        <translation>Chyba pri načítaní súboru!</translation>
    </message>
    <message>
        <source>The .txt file was not correct!</source>
        <translation>Súbor .txt nebol správny!</translation>
    </message>
    <message>
        <source>Output error!</source>
        <translation>Chyba výstupu!</translation>
    </message>
    <message>
        <source>Do you want to reset everything? All curves will be removed.</source>
        <translation>Chcete všetko obnoviť? Všetky krivky budú odstránené.</translation>
    </message>
    <message>
        <source>Not allowed to move control points of a %1: move its knots.</source>
        <translation>Kontrolné body krivky typu „%1“ nie je dovolené posúvať: posúvajte jej uzly.</translation>
    </message>
    <message>
        <source>Not allowed to move control points of a composite curve by keyboard!</source>
        <translation>Kontrolné body zloženej krivky nie je dovolené posúvať klávesnicou!</translation>
    </message>
    <message>
        <source>A %1 does not use a parameterization.</source>
        <translation>Krivka typu „%1“ nepoužíva parametrizáciu.</translation>
    </message>
    <message>
        <source>The maximum count of points is %1!</source>
        <translation>Najväčší počet bodov je %1!</translation>
    </message>
    <message>
        <source>A %1 can not have less than %2 points!</source>
        <translation>Krivka typu „%1“ nemôže mať menej ako %2 bodov!</translation>
    </message>
    <message>
        <source>Must fill all values with numbers!</source>
        <translation>Všetky hodnoty musia byť vyplnené číslami!</translation>
    </message>
    <message>
        <source>“%1” is locked: unlock it to change it.</source>
        <translation>„%1“ je zamknutá: na zmenu ju odomknite.</translation>
    </message>
    <message>
        <source>The knots of this %1 do not define a curve: they need at least 4 different positions.</source>
        <translation>Uzly tejto krivky typu „%1“ neurčujú krivku: potrebujú aspoň 4 rôzne polohy.</translation>
    </message>
    <message>
        <source>This is not possible for a %1.</source>
        <translation>Pre krivku typu „%1“ to nie je možné.</translation>
    </message>
    <message>
        <source>Could not read “%1”: %2</source>
        <translation>Nepodarilo sa prečítať súbor „%1“: %2</translation>
    </message>
    <message>
        <source>Could not write “%1”: %2. The file was left as it was.</source>
        <translation>Nepodarilo sa zapísať súbor „%1“: %2. Súbor zostal nezmenený.</translation>
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
</context>
</TS>
