<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="bg">
<context>
    <name>AppActions</name>
    <message>
        <source>File</source>
        <extracomment>Menu title (noun): the file commands.</extracomment>
        <translation>Файл</translation>
    </message>
    <message>
        <source>New, open, save, import and export</source>
        <translation>Създаване, отваряне, запазване, импортиране и експортиране</translation>
    </message>
    <message>
        <source>Open %1</source>
        <translation>Отваряне на %1</translation>
    </message>
    <message>
        <source>Export PNG (view size)…</source>
        <translation>Експортиране в PNG (размер на изгледа)…</translation>
    </message>
    <message>
        <source>Export PNG (2× view size)…</source>
        <translation>Експортиране в PNG (2× размер на изгледа)…</translation>
    </message>
    <message>
        <source>Export PNG (4× view size)…</source>
        <translation>Експортиране в PNG (4× размер на изгледа)…</translation>
    </message>
    <message>
        <source>Export PNG of the whole document (2×)…</source>
        <translation>Експортиране на целия документ в PNG (2×)…</translation>
    </message>
    <message>
        <source>Quit</source>
        <translation>Изход</translation>
    </message>
    <message>
        <source>New Bézier</source>
        <extracomment>Tool-bar button, short for “New Bézier curve”: starts placing the control points of a new Bézier curve.</extracomment>
        <translation>Нова крива на Безие</translation>
    </message>
    <message>
        <source>Place 4 control points to make a cubic Bézier curve (B)</source>
        <translation>Поставете 4 контролни точки, за да създадете кубична крива на Безие (B)</translation>
    </message>
    <message>
        <source>New curve</source>
        <translation>Нова крива</translation>
    </message>
    <message>
        <source>Choose the kind of curve to place</source>
        <translation>Изберете вида крива, която да поставите</translation>
    </message>
    <message>
        <source>Done</source>
        <extracomment>Button: finishes the curve being placed (keeps the points placed so far).</extracomment>
        <translation>Готово</translation>
    </message>
    <message>
        <source>Finish the curve with the points placed so far (Enter)</source>
        <translation>Завършете кривата с поставените досега точки (Enter)</translation>
    </message>
    <message>
        <source>Move points</source>
        <translation>Преместване на точки</translation>
    </message>
    <message>
        <source>Drag points to change curves; drag the canvas to pan (Esc)</source>
        <translation>Плъзнете точките, за да промените кривите; плъзнете платното, за да преместите изгледа (Esc)</translation>
    </message>
    <message>
        <source>Constrained handles</source>
        <translation>Ограничени манипулатори</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Отмяна</translation>
    </message>
    <message>
        <source>Undo (Ctrl+Z)</source>
        <translation>Отмяна (Ctrl+Z)</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Повторение</translation>
    </message>
    <message>
        <source>Redo (Ctrl+Shift+Z)</source>
        <translation>Повторение (Ctrl+Shift+Z)</translation>
    </message>
    <message>
        <source>Reset all</source>
        <translation>Изчистване на всичко</translation>
    </message>
    <message>
        <source>Remove every curve and the background picture</source>
        <translation>Премахване на всички криви и фоновото изображение</translation>
    </message>
    <message>
        <source>Teaching</source>
        <extracomment>Menu title (noun): the teaching views (de Casteljau, degree elevation, basis functions…).</extracomment>
        <translation>Обучение</translation>
    </message>
    <message>
        <source>Views that show how curves are built</source>
        <translation>Изгледи, които показват как се построяват кривите</translation>
    </message>
    <message>
        <source>de Casteljau construction</source>
        <translation>Построение на де Кастелжо</translation>
    </message>
    <message>
        <source>Degree elevation</source>
        <translation>Увеличаване на степента</translation>
    </message>
    <message>
        <source>Compare curve kinds</source>
        <translation>Сравняване на видове криви</translation>
    </message>
    <message>
        <source>Curvature comb and continuity</source>
        <translation>Гребен на кривината и непрекъснатост</translation>
    </message>
    <message>
        <source>Basis functions</source>
        <translation>Базисни функции</translation>
    </message>
    <message>
        <source>Function spline y(x)…</source>
        <translation>Сплайн-функция y(x)…</translation>
    </message>
    <message>
        <source>Runge phenomenon: comparison…</source>
        <translation>Явлението на Рунге: сравнение…</translation>
    </message>
    <message>
        <source>Cubic segments with guide vectors…</source>
        <translation>Кубични сегменти с направляващи вектори…</translation>
    </message>
    <message>
        <source>Presentation mode (F5)</source>
        <translation>Режим на презентация (F5)</translation>
    </message>
    <message>
        <source>Trace</source>
        <extracomment>Menu title: the tools for tracing a pattern from a photo; a title, not an order.</extracomment>
        <translation>Очертаване</translation>
    </message>
    <message>
        <source>Trace a pattern: freehand, calibrate, measure, compare</source>
        <translation>Очертаване на кройка: от ръка, калибриране, измерване, сравнение</translation>
    </message>
    <message>
        <source>Freehand (T)</source>
        <translation>От ръка (T)</translation>
    </message>
    <message>
        <source>Calibrate background (K)</source>
        <translation>Калибриране на фона (K)</translation>
    </message>
    <message>
        <source>Measure distance (M)</source>
        <translation>Измерване на разстояние (M)</translation>
    </message>
    <message>
        <source>Seam length between knots (L)</source>
        <translation>Дължина на шева между възли (L)</translation>
    </message>
    <message>
        <source>Move background (O)</source>
        <translation>Преместване на фона (O)</translation>
    </message>
    <message>
        <source>Snap to knots, grid and marks (S)</source>
        <translation>Прилепване към възли, мрежа и маркери (S)</translation>
    </message>
    <message>
        <source>Lock background</source>
        <translation>Заключване на фона</translation>
    </message>
    <message>
        <source>Zoom in</source>
        <translation>Увеличаване</translation>
    </message>
    <message>
        <source>Zoom in (+)</source>
        <translation>Увеличаване (+)</translation>
    </message>
    <message>
        <source>Zoom out</source>
        <translation>Намаляване</translation>
    </message>
    <message>
        <source>Zoom out (−)</source>
        <translation>Намаляване (−)</translation>
    </message>
    <message>
        <source>Fit to view</source>
        <extracomment>Command: zoom so that all curves fit in the window.</extracomment>
        <translation>Вместване в изгледа</translation>
    </message>
    <message>
        <source>Show all curves (F)</source>
        <translation>Показване на всички криви (F)</translation>
    </message>
    <message>
        <source>Grid</source>
        <extracomment>Toggle (noun): show or hide the grid on the canvas.</extracomment>
        <translation>Мрежа</translation>
    </message>
    <message>
        <source>Show or hide the grid and the axes (G)</source>
        <translation>Показване или скриване на мрежата и осите (G)</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Език</translation>
    </message>
    <message>
        <source>Side panel</source>
        <translation>Страничен панел</translation>
    </message>
    <message>
        <source>Show or hide the side panel: the curves, their points and settings</source>
        <translation>Показване или скриване на страничния панел: кривите, техните точки и настройки</translation>
    </message>
    <message>
        <source>Seam allowance…</source>
        <translation>Добавка за шев…</translation>
    </message>
    <message>
        <source>Calibrate perspective (Shift+K)</source>
        <translation>Калибриране на перспективата (Shift+K)</translation>
    </message>
    <message>
        <source>Make line</source>
        <translation>Изправяне на сегмента</translation>
    </message>
    <message>
        <source>Make the selected segment a straight line; its knots become corners (Shift+L)</source>
        <translation>Превръща избрания сегмент в права линия; възлите му стават ъглови (Shift+L)</translation>
    </message>
    <message>
        <source>Delete knot</source>
        <translation>Изтриване на възел</translation>
    </message>
    <message>
        <source>Delete the selected knot; its two segments become one</source>
        <translation>Изтрива избрания възел; двата му сегмента стават един</translation>
    </message>
    <message>
        <source>Smooth knot</source>
        <translation>Гладък възел</translation>
    </message>
    <message>
        <source>The handles of the selected knot stay on one line (Shift+S)</source>
        <translation>Манипулаторите на избрания възел остават на една права (Shift+S)</translation>
    </message>
    <message>
        <source>Symmetric knot</source>
        <translation>Симетричен възел</translation>
    </message>
    <message>
        <source>The handles of the selected knot mirror each other (Shift+Y)</source>
        <translation>Манипулаторите на избрания възел са огледални един на друг (Shift+Y)</translation>
    </message>
    <message>
        <source>Corner knot</source>
        <translation>Ъглов възел</translation>
    </message>
    <message>
        <source>The handles of the selected knot move independently (Shift+C)</source>
        <translation>Манипулаторите на избрания възел се движат независимо (Shift+C)</translation>
    </message>
    <message>
        <source>Close curve</source>
        <translation>Затваряне на кривата</translation>
    </message>
    <message>
        <source>Join the curve&apos;s last knot to its first; ends that meet become one knot (Shift+O)</source>
        <translation>Свързва последния възел на кривата с първия; краищата, които се срещат, стават един възел (Shift+O)</translation>
    </message>
    <message>
        <source>Join curves</source>
        <translation>Съединяване на криви</translation>
    </message>
    <message>
        <source>Join the selected curve with the curve whose end is nearest to one of its ends (Shift+J)</source>
        <translation>Съединява избраната крива с кривата, чийто край е най-близо до един от краищата ѝ (Shift+J)</translation>
    </message>
    <message>
        <source>Simplify curve…</source>
        <translation>Опростяване на кривата…</translation>
    </message>
    <message>
        <source>Fewer knots within a tolerance you type</source>
        <translation>По-малко възли в рамките на въведения допуск</translation>
    </message>
    <message>
        <source>Trace outline</source>
        <translation>Обрисуване на контура</translation>
    </message>
    <message>
        <source>The handles of composite curves keep their direction and change only their length (or drag with the right button or Shift)</source>
        <translation>Манипулаторите на съставните криви запазват посоката си и променят само дължината си (или плъзнете с десния бутон или с натиснат Shift)</translation>
    </message>
    <message>
        <source>Deviation from a reference curve (D)</source>
        <translation>Отклонение от еталонна крива (D)</translation>
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
        <translation>Мащаб %1</translation>
    </message>
    <message>
        <source>More</source>
        <extracomment>Tool-bar button that opens a menu with the commands that do not fit on the bar.</extracomment>
        <translation>Още</translation>
    </message>
    <message>
        <source>More commands</source>
        <translation>Още команди</translation>
    </message>
</context>
<context>
    <name>BasisPlot</name>
    <message numerus="yes">
        <source>Too many basis functions to draw (%n).</source>
        <translation>
            <numerusform>Твърде много базисни функции за чертане (%n).</numerusform>
            <numerusform>Твърде много базисни функции за чертане (%n).</numerusform>
        </translation>
    </message>
    <message>
        <source>Bernstein polynomials of degree %1</source>
        <translation>Полиноми на Бернщайн от степен %1</translation>
    </message>
    <message>
        <source>B-spline basis functions N(i,k), order k = %1</source>
        <translation>Базисни функции на B-сплайна N(i,k), ред k = %1</translation>
    </message>
    <message>
        <source>Bell functions Bs of degree %1</source>
        <extracomment>Title: the bell-shaped B-spline basis functions Bs (one bell per knot) of degree %1 (a number).</extracomment>
        <translation>Камбановидни функции Bs от степен %1</translation>
    </message>
    <message>
        <source>Hermite basis functions on one segment</source>
        <translation>Базисни функции на Ермит върху един сегмент</translation>
    </message>
    <message>
        <source>Knot vector: %1</source>
        <translation>Възлов вектор: %1</translation>
    </message>
    <message>
        <source> (sum %1)</source>
        <translation> (сума %1)</translation>
    </message>
    <message numerus="yes">
        <source>Hermite basis functions on the curve&apos;s %n segment(s)</source>
        <translation>
            <numerusform>Базисни функции на Ермит върху %n сегмент на кривата</numerusform>
            <numerusform>Базисни функции на Ермит върху %n сегмента на кривата</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>BasisPlotPanel</name>
    <message>
        <source>Collapse the basis functions</source>
        <translation>Свиване на базисните функции</translation>
    </message>
    <message>
        <source>Expand the basis functions</source>
        <translation>Разгъване на базисните функции</translation>
    </message>
    <message>
        <source>Of the selected curve</source>
        <extracomment>Choices of the basis functions plotted: the selected curve&apos;s own, or a family named with its basis.</extracomment>
        <translation>На избраната крива</translation>
    </message>
    <message>
        <source>B-spline</source>
        <translation>B-сплайн</translation>
    </message>
    <message>
        <source>Bell functions</source>
        <translation>Камбановидни функции</translation>
    </message>
    <message>
        <source>Basis functions</source>
        <translation>Базисни функции</translation>
    </message>
    <message>
        <source>Degree</source>
        <translation>Степен</translation>
    </message>
    <message>
        <source>Order</source>
        <extracomment>Label (noun): the order k of the B-spline basis functions (degree + 1), a number.</extracomment>
        <translation>Ред</translation>
    </message>
    <message>
        <source>Functions</source>
        <extracomment>Label (noun): how many basis functions are drawn (a number beside it).</extracomment>
        <translation>Функции</translation>
    </message>
    <message>
        <source>Number of basis functions</source>
        <translation>Брой базисни функции</translation>
    </message>
    <message>
        <source>Close the basis functions</source>
        <translation>Затваряне на базисните функции</translation>
    </message>
    <message>
        <source>Plot of the basis functions; the left and right arrow keys move t</source>
        <translation>Графика на базисните функции; стрелките наляво и надясно местят t</translation>
    </message>
    <message>
        <source>Bernstein basis</source>
        <translation>Базис на Бернщайн</translation>
    </message>
    <message>
        <source>Hermite basis</source>
        <translation>Базис на Ермит</translation>
    </message>
    <message>
        <source>Make the basis functions smaller</source>
        <translation>Смаляване на базисните функции</translation>
    </message>
    <message>
        <source>Enlarge the basis functions</source>
        <translation>Уголемяване на базисните функции</translation>
    </message>
</context>
<context>
    <name>BottomSheet</name>
    <message>
        <source>Panel size: tap to show more, drag to resize</source>
        <translation>Височина на панела: докоснете за повече, плъзнете за промяна на височината</translation>
    </message>
</context>
<context>
    <name>CanvasView</name>
    <message>
        <source>grid %1</source>
        <extracomment>%1 is the grid spacing in the document&apos;s units (a number).</extracomment>
        <translation>мрежа %1</translation>
    </message>
</context>
<context>
    <name>ConfirmDialog</name>
    <message>
        <source>Yes</source>
        <translation>Да</translation>
    </message>
    <message>
        <source>No</source>
        <translation>Не</translation>
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
        <translation>Отмяна на промените</translation>
    </message>
    <message>
        <source>Add row</source>
        <translation>Добавяне на ред</translation>
    </message>
    <message>
        <source>Delete row</source>
        <translation>Изтриване на ред</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>Копиране</translation>
    </message>
</context>
<context>
    <name>FileActions</name>
    <message>
        <source>New</source>
        <extracomment>Command (verb/adjective): start a new, empty document.</extracomment>
        <translation>Нов</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Отваряне…</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Запазване</translation>
    </message>
    <message>
        <source>Save as…</source>
        <translation>Запазване като…</translation>
    </message>
    <message>
        <source>Export SVG…</source>
        <translation>Експортиране в SVG…</translation>
    </message>
    <message>
        <source>Export the selected curve as CSV…</source>
        <translation>Експортиране на избраната крива като CSV…</translation>
    </message>
    <message>
        <source>Append the selected curve to a points file…</source>
        <translation>Добавяне на избраната крива в края на файл с точки…</translation>
    </message>
    <message>
        <source>Kontur documents (*.kontur)</source>
        <translation>Документи на Kontur (*.kontur)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Всички файлове (*)</translation>
    </message>
    <message>
        <source>Open</source>
        <extracomment>Title of the file dialog that opens a document (verb: open a file).</extracomment>
        <translation>Отваряне</translation>
    </message>
    <message>
        <source>Save as</source>
        <translation>Запазване като</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Импортиране</translation>
    </message>
    <message>
        <source>Export SVG</source>
        <translation>Експортиране в SVG</translation>
    </message>
    <message>
        <source>SVG images (*.svg)</source>
        <translation>SVG изображения (*.svg)</translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation>Експортиране в CSV</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV файлове (*.csv)</translation>
    </message>
    <message>
        <source>Append to a points file</source>
        <translation>Добавяне в края на файл с точки</translation>
    </message>
    <message>
        <source>Points files (*.txt)</source>
        <translation>Файлове с точки (*.txt)</translation>
    </message>
    <message>
        <source>Export PNG</source>
        <translation>Експортиране в PNG</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG изображения (*.png)</translation>
    </message>
    <message>
        <source>Load background image</source>
        <translation>Зареждане на фоново изображение</translation>
    </message>
    <message>
        <source>Images (*.png *.jpg *.jpeg *.heic *.heif *.bmp *.gif *.webp)</source>
        <translation>Изображения (*.png *.jpg *.jpeg *.heic *.heif *.bmp *.gif *.webp)</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Незапазени промени</translation>
    </message>
    <message>
        <source>“%1” has changes that are not saved. Save them first?</source>
        <translation>Документът „%1“ има незапазени промени. Да се запазят ли първо?</translation>
    </message>
    <message>
        <source>Don’t save</source>
        <translation>Без запазване</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отказ</translation>
    </message>
    <message>
        <source>Recover unsaved work</source>
        <translation>Възстановяване на незапазената работа</translation>
    </message>
    <message>
        <source>Kontur was not closed properly last time. Recover the unsaved work?</source>
        <translation>Последния път Kontur не беше затворен правилно. Да се възстанови ли незапазената работа?</translation>
    </message>
    <message>
        <source>Recover</source>
        <translation>Възстановяване</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Отхвърляне</translation>
    </message>
    <message>
        <source>Print pattern…</source>
        <translation>Отпечатване на кройката…</translation>
    </message>
    <message>
        <source>Print pattern to PDF</source>
        <translation>Отпечатване на кройката в PDF</translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation>PDF файлове (*.pdf)</translation>
    </message>
    <message>
        <source>Kontur documents and printed patterns (%1)</source>
        <translation>Документи на Kontur и отпечатани кройки (%1)</translation>
    </message>
    <message>
        <source>Import points, CSV, SVG or DXF…</source>
        <translation>Импортиране на точки, CSV, SVG или DXF…</translation>
    </message>
    <message>
        <source>Export DXF with splines…</source>
        <translation>Експортиране в DXF със сплайни…</translation>
    </message>
    <message>
        <source>The exact curves as DXF splines, in the document&apos;s units, for CAD and pattern software</source>
        <translation>Точните криви като DXF сплайни в единиците на документа, за CAD и програми за кройки</translation>
    </message>
    <message>
        <source>Export DXF with polylines…</source>
        <translation>Експортиране в DXF с начупени линии…</translation>
    </message>
    <message>
        <source>The curves as DXF polylines within 0.05 mm, for plotters and cutters without splines</source>
        <translation>Кривите като DXF начупени линии с точност 0,05 мм, за плотери и режещи машини без сплайни</translation>
    </message>
    <message>
        <source>Points, CSV, SVG and DXF files (%1)</source>
        <translation>Файлове с точки, CSV, SVG и DXF (%1)</translation>
    </message>
    <message>
        <source>Points, CSV, SVG, DXF, Kontur files and printed patterns (%1)</source>
        <translation>Файлове с точки, CSV, SVG, DXF, Kontur и отпечатани кройки (%1)</translation>
    </message>
    <message>
        <source>Export DXF</source>
        <translation>Експортиране в DXF</translation>
    </message>
    <message>
        <source>DXF drawings (*.dxf)</source>
        <translation>DXF чертежи (*.dxf)</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Експортиране</translation>
    </message>
    <message>
        <source>Append</source>
        <translation>Добавяне</translation>
    </message>
    <message>
        <source>Export DXF for pattern software (AAMA)…</source>
        <extracomment>AAMA (ASTM D6673) is the DXF that garment pattern software and cutters exchange pieces in.</extracomment>
        <translation>Експортиране в DXF за програми за кройки (AAMA)…</translation>
    </message>
    <message>
        <source>Each closed curve as a pattern piece (ASTM D6673): its seam allowance as the cut line, the curve as the sew line, polylines within 0.05 mm</source>
        <translation>Всяка затворена крива като детайл от кройка (ASTM D6673): добавката ѝ за шев като линия на рязане, кривата като линия на шева, начупени линии с точност 0,05 мм</translation>
    </message>
    <message>
        <source>Export DXF for pattern software</source>
        <translation>Експортиране в DXF за програми за кройки</translation>
    </message>
</context>
<context>
    <name>FileBrowserDialog</name>
    <message>
        <source>Save</source>
        <translation>Запазване</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Отваряне</translation>
    </message>
</context>
<context>
    <name>FileBrowserPage</name>
    <message>
        <source>Up one folder</source>
        <extracomment>File dialog: go to the folder that contains this one.</extracomment>
        <translation>Една папка нагоре</translation>
    </message>
    <message>
        <source>Folder or file path</source>
        <extracomment>File dialog: the field that shows the folder&apos;s path and takes a typed one.</extracomment>
        <translation>Път до папка или файл</translation>
    </message>
    <message>
        <source>Go</source>
        <extracomment>File dialog: go to the folder or file typed into the path field.</extracomment>
        <translation>Отиване</translation>
    </message>
    <message>
        <source>There is no folder or file “%1”.</source>
        <translation>Няма папка или файл „%1“.</translation>
    </message>
    <message>
        <source>The folder “%1” cannot be read.</source>
        <translation>Папката „%1“ не може да бъде прочетена.</translation>
    </message>
    <message>
        <source>Type a name for the file.</source>
        <translation>Въведете име на файла.</translation>
    </message>
    <message>
        <source>No folders and no matching files here.</source>
        <extracomment>File dialog: the folder shown has no subfolder and no file that the filter lets through.</extracomment>
        <translation>Тук няма папки, нито подходящи файлове.</translation>
    </message>
    <message>
        <source>Files of type</source>
        <extracomment>File dialog: which kinds of files the list shows.</extracomment>
        <translation>Тип файлове</translation>
    </message>
    <message>
        <source>Name</source>
        <extracomment>File dialog: the name of the file to save.</extracomment>
        <translation>Име</translation>
    </message>
    <message>
        <source>File name</source>
        <translation>Име на файл</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отказ</translation>
    </message>
    <message>
        <source>Replace the file?</source>
        <translation>Да се замени ли файлът?</translation>
    </message>
    <message>
        <source>“%1” already exists. Replace it?</source>
        <translation>„%1“ вече съществува. Да се замени ли?</translation>
    </message>
    <message>
        <source>Replace</source>
        <translation>Замяна</translation>
    </message>
</context>
<context>
    <name>FirstRunHint</name>
    <message>
        <source>New curve</source>
        <translation>Нова крива</translation>
    </message>
    <message>
        <source>Tap four points of a Bézier curve</source>
        <translation>Докоснете четири точки на крива на Безие</translation>
    </message>
    <message>
        <source>Open a file</source>
        <translation>Отваряне на файл</translation>
    </message>
    <message>
        <source>A Kontur document</source>
        <translation>Документ на Kontur</translation>
    </message>
    <message>
        <source>Trace a picture</source>
        <translation>Очертаване на изображение</translation>
    </message>
    <message>
        <source>Load a photo or scan and draw over it</source>
        <translation>Заредете снимка или сканирано изображение и чертайте върху него</translation>
    </message>
</context>
<context>
    <name>FunctionSplinePlot</name>
    <message>
        <source>Change the function spline</source>
        <translation>Промяна на сплайн-функцията</translation>
    </message>
</context>
<context>
    <name>FunctionSplineView</name>
    <message>
        <source>Function spline y(x)</source>
        <translation>Сплайн-функция y(x)</translation>
    </message>
    <message>
        <source>Close</source>
        <extracomment>Button (verb): closes this teaching view and returns to the drawing.</extracomment>
        <translation>Затваряне</translation>
    </message>
    <message>
        <source>Spline</source>
        <extracomment>Heading (noun): the kind of spline to draw.</extracomment>
        <translation>Сплайн</translation>
    </message>
    <message>
        <source>Natural spline</source>
        <translation>Естествен сплайн</translation>
    </message>
    <message>
        <source>Clamped spline (C-spline)</source>
        <translation>Закрепен сплайн (C-сплайн)</translation>
    </message>
    <message>
        <source>Hermite spline (H-spline)</source>
        <translation>Сплайн на Ермит (H-сплайн)</translation>
    </message>
    <message>
        <source>Global B-spline</source>
        <translation>Глобален B-сплайн</translation>
    </message>
    <message>
        <source>B-spline of bell functions</source>
        <translation>B-сплайн от камбановидни функции</translation>
    </message>
    <message>
        <source>Control values</source>
        <translation>Контролни стойности</translation>
    </message>
    <message>
        <source>Function values</source>
        <translation>Стойности на функцията</translation>
    </message>
    <message>
        <source>Regular (uniform) knots</source>
        <translation>Регулярни (равномерни) възли</translation>
    </message>
    <message>
        <source>Interval</source>
        <extracomment>Heading (noun): the interval [a, b] of evenly spaced knots; otherwise the knots x₀ … xₙ are typed one by one.</extracomment>
        <translation>Интервал</translation>
    </message>
    <message>
        <source>Knots</source>
        <translation>Възли</translation>
    </message>
    <message>
        <source>Derivatives (one per knot)</source>
        <translation>Производни (по една за всеки възел)</translation>
    </message>
    <message>
        <source>Derivatives (first and last knot)</source>
        <translation>Производни (в първия и последния възел)</translation>
    </message>
    <message>
        <source>Derivatives</source>
        <extracomment>Screen-reader name of the field for the derivatives at the two ends (clamped spline).</extracomment>
        <translation>Производни</translation>
    </message>
    <message>
        <source>Draw</source>
        <extracomment>Button (verb): draws the spline from the values typed above.</extracomment>
        <translation>Начертаване</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Отмяна</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Повторение</translation>
    </message>
    <message>
        <source>Interpolating polynomial through the same points</source>
        <translation>Интерполационен полином през същите точки</translation>
    </message>
    <message>
        <source>Runge&apos;s example</source>
        <translation>Примерът на Рунге</translation>
    </message>
    <message>
        <source>Points of Runge&apos;s example</source>
        <translation>Точки от примера на Рунге</translation>
    </message>
    <message>
        <source>Drag a green knot up or down, or a grey handle to change the derivative: its slope to the knot is the derivative.</source>
        <translation>Плъзнете зелен възел нагоре или надолу или сив манипулатор, за да промените производната: наклонът му към възела е производната.</translation>
    </message>
    <message>
        <source>Runge phenomenon: comparison</source>
        <translation>Явлението на Рунге: сравнение</translation>
    </message>
    <message>
        <source>Solver</source>
        <translation>Метод за решаване</translation>
    </message>
    <message>
        <source>Classical: k − 2 unknowns</source>
        <translation>Класически: k − 2 неизвестни</translation>
    </message>
    <message>
        <source>Török: half-size system</source>
        <translation>Тьорьок: система с половин размер</translation>
    </message>
    <message>
        <source>Add to document</source>
        <translation>Добавяне към документа</translation>
    </message>
    <message>
        <source>Added to the document as “%1”.</source>
        <translation>Добавено към документа като „%1“.</translation>
    </message>
    <message>
        <source>Add this spline to the drawing as a curve (undone in one step)</source>
        <translation>Добавяне на този сплайн към чертежа като крива (отменя се с една стъпка)</translation>
    </message>
    <message>
        <source>Course examples</source>
        <extracomment>Heading: buttons that load the course&apos;s worked examples.</extracomment>
        <translation>Примери от курса</translation>
    </message>
    <message>
        <source>Török&apos;s example</source>
        <extracomment>Button: loads Török&apos;s example (values 3 2 −1 0,5, end slopes 0, his solver).</extracomment>
        <translation>Примерът на Тьорьок</translation>
    </message>
    <message>
        <source>Example 1.23</source>
        <extracomment>Button: loads the course&apos;s Example 1.23 (a global B-spline); keep the number.</extracomment>
        <translation>Пример 1.23</translation>
    </message>
    <message>
        <source>Example 1.30</source>
        <extracomment>Button: loads the course&apos;s Example 1.30 (a Hermite spline); keep the number.</extracomment>
        <translation>Пример 1.30</translation>
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
        <translation>Натиснете „Нова крива на Безие“ и докоснете 4 точки, за да начертаете първата си крива.</translation>
    </message>
    <message>
        <source>Drag a point to move it. Drag the canvas to pan; pinch or scroll to zoom.</source>
        <translation>Плъзнете точка, за да я преместите. Плъзнете платното, за да преместите изгледа; мащабирайте с два пръста или с колелцето.</translation>
    </message>
    <message>
        <source>New curve: tap or click its points (%1 placed). Press Done to finish, Esc to cancel.</source>
        <translation>Нова крива: докоснете точките ѝ или щракнете върху тях (поставени: %1). Натиснете „Готово“ за край, Esc за отказ.</translation>
    </message>
    <message>
        <source>New curve: tap or click point %1 of %2. Esc cancels.</source>
        <translation>Нова крива: докоснете или щракнете, за да поставите точка %1 от %2. Esc за отказ.</translation>
    </message>
    <message>
        <source>Grainline: tap its other end.</source>
        <translation>Посока на основата: докоснете другия ѝ край.</translation>
    </message>
    <message>
        <source>Grainline: tap one end, then the other.</source>
        <translation>Посока на основата: докоснете единия край, после другия.</translation>
    </message>
    <message>
        <source>On fold: tap the fold line&apos;s other end.</source>
        <translation>На сгъвка: докоснете другия край на линията на сгъвката.</translation>
    </message>
    <message>
        <source>On fold: tap one end of the fold line, then the other.</source>
        <translation>На сгъвка: докоснете единия край на линията на сгъвката, после другия.</translation>
    </message>
    <message>
        <source>Notch: tap the seam to place one; drag a notch to slide it along the seam.</source>
        <translation>Засечка: докоснете шева, за да поставите засечка; плъзнете засечката, за да я преместите по шева.</translation>
    </message>
    <message>
        <source>Drill hole: tap where it goes.</source>
        <translation>Пробив: докоснете мястото, където да бъде.</translation>
    </message>
    <message>
        <source>Delete mark: tap a notch, drill hole, grainline or fold line.</source>
        <translation>Изтриване на знак: докоснете засечка, пробив, посоката на основата или линията на сгъвката.</translation>
    </message>
    <message>
        <source>Seam allowance: tap a seam, then set its width in the bar.</source>
        <translation>Добавка за шев: докоснете шев, после задайте ширината му в лентата.</translation>
    </message>
</context>
<context>
    <name>MessageBanner</name>
    <message>
        <source>Close message</source>
        <translation>Затваряне на съобщението</translation>
    </message>
    <message>
        <source>Change units…</source>
        <extracomment>Button in the message that a DXF without units was read in the units chosen for such files.</extracomment>
        <translation>Смяна на мерните единици…</translation>
    </message>
</context>
<context>
    <name>NumberStepper</name>
    <message>
        <source>%1 of %2</source>
        <extracomment>Which number of a typed list the − and + buttons change: %1 its place, %2 how many there are.</extracomment>
        <translation>%1 от %2</translation>
    </message>
    <message>
        <source>Previous number</source>
        <extracomment>Screen-reader name: chooses the previous number of the list for the − and + buttons.</extracomment>
        <translation>Предишно число</translation>
    </message>
    <message>
        <source>Next number</source>
        <extracomment>Screen-reader name: chooses the next number of the list for the − and + buttons.</extracomment>
        <translation>Следващо число</translation>
    </message>
    <message>
        <source>Decrease the marked number</source>
        <extracomment>Screen-reader name: makes the marked number of the list smaller by the step shown.</extracomment>
        <translation>Намали маркираното число</translation>
    </message>
    <message>
        <source>Increase the marked number</source>
        <extracomment>Screen-reader name: makes the marked number of the list larger by the step shown.</extracomment>
        <translation>Увеличи маркираното число</translation>
    </message>
</context>
<context>
    <name>PanelDrawer</name>
    <message>
        <source>Curves and settings</source>
        <translation>Криви и настройки</translation>
    </message>
    <message>
        <source>Unpin</source>
        <extracomment>Button (verb): let the side panel slide over the canvas instead of staying beside it.</extracomment>
        <translation>Откачане</translation>
    </message>
    <message>
        <source>Pin</source>
        <extracomment>Button (verb): keep the side panel open beside the canvas.</extracomment>
        <translation>Закачане</translation>
    </message>
    <message>
        <source>Unpin the panel: let it slide over the canvas</source>
        <translation>Откачане на панела: да се плъзга върху платното</translation>
    </message>
    <message>
        <source>Pin the panel beside the canvas</source>
        <translation>Закачане на панела до платното</translation>
    </message>
</context>
<context>
    <name>PieceBar</name>
    <message>
        <source>Pattern piece</source>
        <extracomment>Title of the bar that edits a garment pattern piece&apos;s marks.</extracomment>
        <translation>Детайл от кройката</translation>
    </message>
    <message>
        <source>Make a pattern piece</source>
        <translation>Направи детайл от кройката</translation>
    </message>
    <message>
        <source>Select a closed curve: the outline of a pattern piece.</source>
        <translation>Изберете затворена крива: контура на детайл от кройката.</translation>
    </message>
    <message>
        <source>Size</source>
        <extracomment>A garment size (38, M) of the pattern piece.</extracomment>
        <translation>Размер</translation>
    </message>
    <message>
        <source>Cut</source>
        <extracomment>How many pieces to cut from the fabric (“cut 2”).</extracomment>
        <translation>Крои се</translation>
    </message>
    <message>
        <source>How many to cut</source>
        <translation>Колко да се скроят</translation>
    </message>
    <message>
        <source>Material</source>
        <extracomment>The fabric the pattern piece is cut from.</extracomment>
        <translation>Материал</translation>
    </message>
    <message>
        <source>Grainline</source>
        <extracomment>Tool: draw the pattern piece&apos;s grainline with two taps.</extracomment>
        <translation>Посока на основата</translation>
    </message>
    <message>
        <source>On fold</source>
        <extracomment>Tool: the fold line, the edge laid on the fabric&apos;s fold (two taps).</extracomment>
        <translation>На сгъвка</translation>
    </message>
    <message>
        <source>Notch</source>
        <extracomment>Tool: place a notch by tapping the seam.</extracomment>
        <translation>Засечка</translation>
    </message>
    <message>
        <source>Slit notch</source>
        <translation>Права засечка</translation>
    </message>
    <message>
        <source>V notch</source>
        <translation>V-образна засечка</translation>
    </message>
    <message>
        <source>Castle notch</source>
        <translation>Правоъгълна засечка</translation>
    </message>
    <message>
        <source>Notch kind</source>
        <translation>Вид засечка</translation>
    </message>
    <message>
        <source>Drill hole</source>
        <extracomment>Tool: mark a drill hole by a tap.</extracomment>
        <translation>Пробив</translation>
    </message>
    <message>
        <source>Delete mark</source>
        <extracomment>Tool: delete the notch, drill hole, grainline or fold line tapped.</extracomment>
        <translation>Изтрий знак</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>Готово</translation>
    </message>
    <message>
        <source>Close the pattern piece bar</source>
        <translation>Затвори лентата на детайла от кройката</translation>
    </message>
    <message>
        <source>Seam allowance</source>
        <extracomment>Tool: tap a seam of the pattern piece to set its own seam allowance width.</extracomment>
        <translation>Добавка за шев</translation>
    </message>
    <message>
        <source>Seam %1</source>
        <extracomment>The seam tapped (numbered from 1 along the piece) whose seam allowance the bar shows.</extracomment>
        <translation>Шев %1</translation>
    </message>
    <message>
        <source>Seam allowance %1 %2 narrower</source>
        <translation>Добавка за шев с %1 %2 по-тясна</translation>
    </message>
    <message>
        <source>Seam allowance of the seam</source>
        <translation>Добавка за този шев</translation>
    </message>
    <message>
        <source>Seam allowance %1 %2 wider</source>
        <translation>Добавка за шев с %1 %2 по-широка</translation>
    </message>
    <message>
        <source>As the piece</source>
        <extracomment>Give the seam the piece&apos;s own seam allowance width again.</extracomment>
        <translation>Като детайла</translation>
    </message>
    <message>
        <source>Hem: turned-back corners</source>
        <extracomment>Toggle: the tapped seam is a hem, so its seam allowance&apos;s corners are turned back (mirrored about the hem line) rather than mitred.</extracomment>
        <translation>Подгъв: обърнати ъгли</translation>
    </message>
</context>
<context>
    <name>PracticumPlot</name>
    <message>
        <source>Change the segments</source>
        <translation>Промяна на сегментите</translation>
    </message>
</context>
<context>
    <name>PracticumView</name>
    <message>
        <source>Cubic segments</source>
        <translation>Кубични сегменти</translation>
    </message>
    <message>
        <source>Close</source>
        <extracomment>Button (verb): closes this teaching view and returns to the drawing.</extracomment>
        <translation>Затваряне</translation>
    </message>
    <message>
        <source>Parametric segment</source>
        <translation>Параметричен сегмент</translation>
    </message>
    <message>
        <source>Spline through several points</source>
        <translation>Сплайн през няколко точки</translation>
    </message>
    <message>
        <source>Kind of segment</source>
        <translation>Вид сегмент</translation>
    </message>
    <message>
        <source>Lines per segment</source>
        <translation>Брой отсечки в сегмент</translation>
    </message>
    <message>
        <source>By lines</source>
        <translation>С отсечки</translation>
    </message>
    <message>
        <source>By points</source>
        <translation>С точки</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Отмяна</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Повторение</translation>
    </message>
    <message>
        <source>Drag the green points, or the grey grips at the ends of the guide vectors to change the end directions.</source>
        <translation>Плъзнете зелените точки или сивите манипулатори в краищата на направляващите вектори, за да промените посоките в краищата.</translation>
    </message>
    <message>
        <source>Function segment y(x)</source>
        <translation>Функционален сегмент y(x)</translation>
    </message>
    <message>
        <source>Test example</source>
        <translation>Тестов пример</translation>
    </message>
    <message>
        <source>Segment example</source>
        <extracomment>Button: loads the practicum&apos;s single-segment example (KG-202: two points, guide vectors rising and falling at 45°), in the segment kind chosen.</extracomment>
        <translation>Пример за сегмент</translation>
    </message>
</context>
<context>
    <name>PrintDialog</name>
    <message>
        <source>Print pattern</source>
        <translation>Отпечатване на кройката</translation>
    </message>
    <message>
        <source>Print to PDF…</source>
        <translation>Отпечатване в PDF…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отказ</translation>
    </message>
    <message>
        <source>Paper</source>
        <translation>Хартия</translation>
    </message>
    <message>
        <source>Letter</source>
        <extracomment>The US paper size Letter (8.5 × 11 in), not a letter of the alphabet or a message.</extracomment>
        <translation>Letter (САЩ)</translation>
    </message>
    <message>
        <source>Orientation</source>
        <translation>Ориентация</translation>
    </message>
    <message>
        <source>Automatic (fewer pages)</source>
        <translation>Автоматично (по-малко страници)</translation>
    </message>
    <message>
        <source>Portrait</source>
        <translation>Портретна</translation>
    </message>
    <message>
        <source>Landscape</source>
        <translation>Пейзажна</translation>
    </message>
    <message>
        <source>Overlap (mm)</source>
        <translation>Застъпване (мм)</translation>
    </message>
    <message numerus="yes">
        <source>%n page(s) to tape together: %1 × %2 (rows × columns), %3.</source>
        <translation>
            <numerusform>%n страница за слепване: %1 × %2 (редове × колони), %3.</numerusform>
            <numerusform>%n страници за слепване: %1 × %2 (редове × колони), %3.</numerusform>
        </translation>
    </message>
    <message>
        <source>landscape</source>
        <translation>пейзажна ориентация</translation>
    </message>
    <message>
        <source>portrait</source>
        <translation>портретна ориентация</translation>
    </message>
    <message>
        <source>Before them, a first page with a 10 cm test square and the overview. Print at 100 % (actual size). The visible curves are printed; the background picture is not.</source>
        <translation>Преди тях има първа страница с контролен квадрат 10 см и общ изглед. Печатайте в мащаб 100 % (действителен размер). Отпечатват се видимите криви, фоновото изображение — не.</translation>
    </message>
    <message>
        <source>The drawing is in px: it is printed at 96 px per inch. Choose real units for true size.</source>
        <translation>Чертежът е в пиксели (px): отпечатва се при 96 px на инч. За действителен размер изберете реални мерни единици.</translation>
    </message>
</context>
<context>
    <name>SeamAllowanceDialog</name>
    <message>
        <source>Seam allowance</source>
        <translation>Добавка за шев</translation>
    </message>
    <message>
        <source>Width (%1)</source>
        <extracomment>Label: the seam allowance&apos;s width; %1 is the unit (mm, cm…).</extracomment>
        <translation>Ширина (%1)</translation>
    </message>
    <message>
        <source>Seam allowance width</source>
        <translation>Ширина на добавката за шев</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Страна</translation>
    </message>
    <message>
        <source>Outside</source>
        <translation>Отвън</translation>
    </message>
    <message>
        <source>Inside</source>
        <translation>Отвътре</translation>
    </message>
    <message>
        <source>Left of the direction</source>
        <translation>Отляво на посоката</translation>
    </message>
    <message>
        <source>Right of the direction</source>
        <translation>Отдясно на посоката</translation>
    </message>
    <message>
        <source>Corners</source>
        <translation>Ъгли</translation>
    </message>
    <message>
        <source>Mitered</source>
        <translation>Остри</translation>
    </message>
    <message>
        <source>Bevelled</source>
        <translation>Скосени</translation>
    </message>
    <message>
        <source>Rounded</source>
        <translation>Заоблени</translation>
    </message>
    <message>
        <source>Miter limit (%1)</source>
        <extracomment>Label: the longest pointed corner; %1 is the unit (mm, cm…).</extracomment>
        <translation>Граница на острия ъгъл (%1)</translation>
    </message>
    <message>
        <source>Miter limit</source>
        <translation>Граница на острия ъгъл</translation>
    </message>
    <message>
        <source>Apply</source>
        <extracomment>Button (verb): applies the changed settings to this seam allowance.</extracomment>
        <translation>Прилагане</translation>
    </message>
    <message>
        <source>Add</source>
        <extracomment>Button (verb): adds a seam allowance to the selected curve.</extracomment>
        <translation>Добавяне</translation>
    </message>
    <message>
        <source>Detach</source>
        <extracomment>Button (verb): cut the link between the seam allowance and its curve, so it can be edited on its own.</extracomment>
        <translation>Отделяне</translation>
    </message>
    <message>
        <source>Detach from its curve</source>
        <translation>Отделяне от кривата ѝ</translation>
    </message>
    <message>
        <source>Close</source>
        <extracomment>Button (verb): closes this dialog.</extracomment>
        <translation>Затваряне</translation>
    </message>
    <message>
        <source>Computing the seam allowance…</source>
        <translation>Изчисляване на добавката за шев…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отказ</translation>
    </message>
    <message>
        <source>Cancel the seam allowance</source>
        <translation>Отказ от изчисляването на добавката за шев</translation>
    </message>
</context>
<context>
    <name>SidePanel</name>
    <message>
        <source>Curves</source>
        <translation>Криви</translation>
    </message>
    <message>
        <source>No curves yet.</source>
        <translation>Все още няма криви.</translation>
    </message>
    <message>
        <source>%1 · cannot be drawn from these points</source>
        <translation>%1 · не може да се начертае от тези точки</translation>
    </message>
    <message numerus="yes">
        <source>%1 · %n point(s) · length %2</source>
        <extracomment>%1 is the curve&apos;s kind, %2 its length with its unit (12.5 mm).</extracomment>
        <translatorcomment>Qt has two plural forms for Bulgarian (1 / other), so 21 gives „21 точки“ (normative: двадесет и една точка); accepted in UI text with digits.</translatorcomment>
        <translation>
            <numerusform>%1 · %n точка · дължина %2</numerusform>
            <numerusform>%1 · %n точки · дължина %2</numerusform>
        </translation>
    </message>
    <message>
        <source>Selected curve</source>
        <translation>Избрана крива</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Име</translation>
    </message>
    <message>
        <source>Kind</source>
        <extracomment>Label (noun): the kind of the selected curve, for example “Bézier curve” or “Natural spline”.</extracomment>
        <translation>Вид</translation>
    </message>
    <message>
        <source>degree %1</source>
        <translation>степен %1</translation>
    </message>
    <message>
        <source>Parameterization</source>
        <translation>Параметризация</translation>
    </message>
    <message>
        <source>Uniform</source>
        <translation>Равномерна</translation>
    </message>
    <message>
        <source>Chord length</source>
        <translation>По дължина на хордите</translation>
    </message>
    <message>
        <source>Centripetal</source>
        <translation>Центростремителна</translation>
    </message>
    <message>
        <source>Order</source>
        <extracomment>Label (noun): the order k of a B-spline (degree + 1), a number; not a sequence and not a command.</extracomment>
        <translation>Ред на сплайна</translation>
    </message>
    <message>
        <source>Node type</source>
        <translation>Вид на възела</translation>
    </message>
    <message>
        <source>Smooth</source>
        <extracomment>Knot type: the handles on both sides stay on one line (G1).</extracomment>
        <translation>Гладък</translation>
    </message>
    <message>
        <source>Symmetric</source>
        <extracomment>Knot type: the handles on both sides stay on one line and have equal lengths (C1).</extracomment>
        <translation>Симетричен</translation>
    </message>
    <message>
        <source>Corner</source>
        <extracomment>Knot type: the handles on both sides move independently (a corner).</extracomment>
        <translation>Ъглов</translation>
    </message>
    <message>
        <source>Colour</source>
        <translation>Цвят</translation>
    </message>
    <message>
        <source>Visible</source>
        <translation>Видима</translation>
    </message>
    <message>
        <source>Locked</source>
        <translation>Заключена</translation>
    </message>
    <message>
        <source>Close curve</source>
        <translation>Затваряне на кривата</translation>
    </message>
    <message>
        <source>Move up</source>
        <translation>Преместване нагоре</translation>
    </message>
    <message>
        <source>Move down</source>
        <translation>Преместване надолу</translation>
    </message>
    <message>
        <source>Delete curve</source>
        <translation>Изтриване на кривата</translation>
    </message>
    <message>
        <source>Coordinates</source>
        <translation>Координати</translation>
    </message>
    <message>
        <source>Info</source>
        <extracomment>Heading (noun): figures about the selected curve (length, fit error, continuity).</extracomment>
        <translation>Информация</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Дължина</translation>
    </message>
    <message>
        <source>Fit error (RMS / max)</source>
        <translation>Грешка на приближението (RMS / макс.)</translation>
    </message>
    <message>
        <source>Continuity</source>
        <translation>Непрекъснатост</translation>
    </message>
    <message>
        <source>joint %1: %2</source>
        <translation>съединение %1: %2</translation>
    </message>
    <message>
        <source>Background image</source>
        <translation>Фоново изображение</translation>
    </message>
    <message>
        <source>Load image…</source>
        <translation>Зареждане на изображение…</translation>
    </message>
    <message>
        <source>Show background</source>
        <translation>Показване на фона</translation>
    </message>
    <message>
        <source>Opacity</source>
        <translation>Непрозрачност</translation>
    </message>
    <message>
        <source>Remove background</source>
        <translation>Премахване на фона</translation>
    </message>
    <message>
        <source>%1 / %2</source>
        <extracomment>The fit error as RMS / maximum: %1 and %2 are numbers.</extracomment>
        <translation>%1 / %2</translation>
    </message>
    <message>
        <source>No curve selected. Tap a curve to edit it.</source>
        <translation>Няма избрана крива. Докоснете крива, за да я промените.</translation>
    </message>
    <message>
        <source>Curve visible</source>
        <translation>Кривата е видима</translation>
    </message>
    <message>
        <source>Curve locked</source>
        <translation>Кривата е заключена</translation>
    </message>
    <message>
        <source>Curve name</source>
        <translation>Име на кривата</translation>
    </message>
    <message>
        <source>Black</source>
        <translation>Черен</translation>
    </message>
    <message>
        <source>Red</source>
        <translation>Червен</translation>
    </message>
    <message>
        <source>Blue</source>
        <translation>Син</translation>
    </message>
    <message>
        <source>Green</source>
        <translation>Зелен</translation>
    </message>
    <message>
        <source>Orange</source>
        <translation>Оранжев</translation>
    </message>
    <message>
        <source>Purple</source>
        <translation>Лилав</translation>
    </message>
    <message>
        <source>Teal</source>
        <translation>Синьозелен</translation>
    </message>
    <message>
        <source>Brown</source>
        <translation>Кафяв</translation>
    </message>
    <message>
        <source>Colour: %1</source>
        <translation>Цвят: %1</translation>
    </message>
    <message>
        <source>Load background image</source>
        <translation>Зареждане на фоново изображение</translation>
    </message>
    <message>
        <source>Background opacity</source>
        <translation>Непрозрачност на фона</translation>
    </message>
    <message>
        <source>Pattern piece…</source>
        <extracomment>Opens the bar that makes the closed curve a garment pattern piece and edits its marks.</extracomment>
        <translation>Детайл от кройката…</translation>
    </message>
    <message>
        <source>Pattern piece</source>
        <translation>Детайл от кройката</translation>
    </message>
</context>
<context>
    <name>SimplifyDialog</name>
    <message>
        <source>Simplify curve</source>
        <translation>Опростяване на кривата</translation>
    </message>
    <message>
        <source>The new curve stays within this distance of the old one.</source>
        <translation>Новата крива остава в рамките на това разстояние от старата.</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Допуск</translation>
    </message>
    <message>
        <source>Simplify</source>
        <translation>Опростяване</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отказ</translation>
    </message>
</context>
<context>
    <name>TeachingBar</name>
    <message>
        <source>de Casteljau</source>
        <translation>де Кастелжо</translation>
    </message>
    <message>
        <source>Degree elevation</source>
        <translation>Увеличаване на степента</translation>
    </message>
    <message>
        <source>Compare</source>
        <extracomment>Name of a teaching view (verb used as a title): compare curve kinds or parameterizations side by side.</extracomment>
        <translation>Сравнение</translation>
    </message>
    <message>
        <source>Curvature comb</source>
        <translation>Гребен на кривината</translation>
    </message>
    <message>
        <source>Select a Bézier curve.</source>
        <translation>Изберете крива на Безие.</translation>
    </message>
    <message>
        <source>Select a curve.</source>
        <translation>Изберете крива.</translation>
    </message>
    <message>
        <source>t = %1</source>
        <extracomment>The curve parameter t and its value (a number); keep “t”.</extracomment>
        <translation>t = %1</translation>
    </message>
    <message>
        <source>Parameter t</source>
        <translation>Параметър t</translation>
    </message>
    <message numerus="yes">
        <source>degree %1 → %2 (%n point(s))</source>
        <translation>
            <numerusform>степен %1 → %2 (%n точка)</numerusform>
            <numerusform>степен %1 → %2 (%n точки)</numerusform>
        </translation>
    </message>
    <message>
        <source>Elevation steps</source>
        <translation>Стъпки на увеличаване на степента</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Пауза</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Пускане</translation>
    </message>
    <message>
        <source>Play or pause the animation (P)</source>
        <translation>Пускане или пауза на анимацията (P)</translation>
    </message>
    <message>
        <source>Direction</source>
        <extracomment>Screen-reader name of the button that reverses the direction of the animation (forwards or backwards in t).</extracomment>
        <translation>Посока</translation>
    </message>
    <message>
        <source>Forward; press to go backward</source>
        <translation>Напред; натиснете за назад</translation>
    </message>
    <message>
        <source>Backward; press to go forward</source>
        <translation>Назад; натиснете за напред</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Скорост</translation>
    </message>
    <message>
        <source>%1×</source>
        <extracomment>Animation speed factor: %1 is a number (0,5 → “0,5×”).</extracomment>
        <translation>%1×</translation>
    </message>
    <message>
        <source>Split at t</source>
        <translation>Разделяне при t</translation>
    </message>
    <message>
        <source>Reduce degree</source>
        <translation>Понижаване на степента</translation>
    </message>
    <message>
        <source>Replace the curve by the closest curve of one degree less</source>
        <translation>Замяна на кривата с най-близката крива с една степен по-ниска</translation>
    </message>
    <message>
        <source>reduction error %1</source>
        <extracomment>Degree reduction: %1 is the largest distance between the curve and its reduced curve (a number).</extracomment>
        <translation>грешка от понижаването %1</translation>
    </message>
    <message>
        <source>Alt+click or long press: add or remove a control point</source>
        <translation>Alt+щракване или продължително натискане: добавяне или премахване на контролна точка</translation>
    </message>
    <message>
        <source>Curve kinds</source>
        <extracomment>What the Compare view sets side by side: one curve drawn as each kind, or with each parameterization.</extracomment>
        <translation>Видове криви</translation>
    </message>
    <message>
        <source>Parameterizations</source>
        <translation>Параметризации</translation>
    </message>
    <message>
        <source>Scale %1</source>
        <extracomment>%1 is the scale factor of the curvature comb (a number such as 2,5).</extracomment>
        <translation>Мащаб %1</translation>
    </message>
    <message>
        <source>Comb scale</source>
        <translation>Мащаб на гребена</translation>
    </message>
    <message>
        <source>All curves</source>
        <translation>Всички криви</translation>
    </message>
    <message>
        <source>Close</source>
        <extracomment>Button (verb): closes the teaching view and returns to the drawing.</extracomment>
        <translation>Затваряне</translation>
    </message>
    <message>
        <source>Leave the teaching view</source>
        <translation>Изход от учебния изглед</translation>
    </message>
    <message>
        <source>Split the curve at t into two curves (a spline becomes a composite curve first)</source>
        <translation>Разделяне на кривата при t на две криви (сплайнът първо става съставна крива)</translation>
    </message>
    <message>
        <source>One elevation step less</source>
        <translation>С една стъпка на увеличаване по-малко</translation>
    </message>
    <message>
        <source>One elevation step more</source>
        <translation>С една стъпка на увеличаване повече</translation>
    </message>
    <message>
        <source>One step back in t</source>
        <translation>С една стъпка назад по t</translation>
    </message>
    <message>
        <source>One step forward in t</source>
        <translation>С една стъпка напред по t</translation>
    </message>
</context>
<context>
    <name>TeachingOverlay</name>
    <message>
        <source>%1 (not possible for these points)</source>
        <translation>%1 (невъзможно за тези точки)</translation>
    </message>
</context>
<context>
    <name>TraceBar</name>
    <message>
        <source>Freehand</source>
        <translation>От ръка</translation>
    </message>
    <message>
        <source>Calibrate</source>
        <translation>Калибриране</translation>
    </message>
    <message>
        <source>Measure</source>
        <translation>Измерване</translation>
    </message>
    <message>
        <source>Seam length</source>
        <translation>Дължина на шева</translation>
    </message>
    <message>
        <source>Deviation</source>
        <translation>Отклонение</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Допуск</translation>
    </message>
    <message numerus="yes">
        <source>last stroke: %n segment(s)</source>
        <translation>
            <numerusform>последен щрих: %n сегмент</numerusform>
            <numerusform>последен щрих: %n сегмента</numerusform>
        </translation>
    </message>
    <message>
        <source>Real distance</source>
        <translation>Реално разстояние</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Мерна единица</translation>
    </message>
    <message>
        <source>Keep the angle</source>
        <translation>Без завъртане</translation>
    </message>
    <message>
        <source>Make it horizontal</source>
        <translation>Хоризонтално</translation>
    </message>
    <message>
        <source>Make it vertical</source>
        <translation>Вертикално</translation>
    </message>
    <message>
        <source>Alignment</source>
        <translation>Подравняване</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Прилагане</translation>
    </message>
    <message>
        <source>Distance %1</source>
        <extracomment>%1 is a length with its unit, for example “12,35 mm”.</extracomment>
        <translation>Разстояние %1</translation>
    </message>
    <message>
        <source>Seam %1</source>
        <extracomment>%1 is the seam length with its unit, for example “412,50 mm”.</extracomment>
        <translation>Шев %1</translation>
    </message>
    <message>
        <source>Maximum %1 · mean %2</source>
        <extracomment>Deviation of a traced curve from the reference curve: %1 and %2 are lengths with their unit.</extracomment>
        <translation>Максимум %1 · средно %2</translation>
    </message>
    <message>
        <source>Snap</source>
        <extracomment>Check box (verb): snap freehand strokes to the edges seen in the picture.</extracomment>
        <translation>Прилепване</translation>
    </message>
    <message>
        <source>Leave the tracing tool</source>
        <translation>Изход от инструмента за очертаване</translation>
    </message>
    <message>
        <source>Move background</source>
        <translation>Преместване на фона</translation>
    </message>
    <message>
        <source>Perspective</source>
        <translation>Перспектива</translation>
    </message>
    <message>
        <source>A4 sheet (210 × 297 mm)</source>
        <translation>Лист A4 (210 × 297 мм)</translation>
    </message>
    <message>
        <source>A3 sheet (297 × 420 mm)</source>
        <translation>Лист A3 (297 × 420 мм)</translation>
    </message>
    <message>
        <source>Letter sheet (8.5 × 11 in)</source>
        <translation>Лист Letter (8,5 × 11″)</translation>
    </message>
    <message>
        <source>Mat square 1 cm</source>
        <translation>Подложка: квадрат 1 см</translation>
    </message>
    <message>
        <source>Mat square 10 cm</source>
        <translation>Подложка: квадрат 10 см</translation>
    </message>
    <message>
        <source>Mat square 1 in</source>
        <translation>Подложка: квадрат 1 инч</translation>
    </message>
    <message>
        <source>Mat square 6 in</source>
        <translation>Подложка: квадрат 6 инча</translation>
    </message>
    <message>
        <source>Other size</source>
        <translation>Друг размер</translation>
    </message>
    <message>
        <source>Known rectangle</source>
        <translation>Известен правоъгълник</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Ширина</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Височина</translation>
    </message>
    <message>
        <source>As marked: landscape</source>
        <translation>Отбелязано: пейзажна</translation>
    </message>
    <message>
        <source>As marked: portrait</source>
        <translation>Отбелязано: портретна</translation>
    </message>
    <message>
        <source>As marked</source>
        <translation>Отбелязано</translation>
    </message>
    <message>
        <source>Portrait</source>
        <translation>Портретна</translation>
    </message>
    <message>
        <source>Landscape</source>
        <translation>Пейзажна</translation>
    </message>
    <message>
        <source>Orientation</source>
        <translation>Ориентация</translation>
    </message>
    <message>
        <source>Clear perspective</source>
        <translation>Премахване на перспективата</translation>
    </message>
    <message>
        <source>Trace outline</source>
        <translation>Обрисуване на контура</translation>
    </message>
    <message>
        <source>Snap to edges</source>
        <translation>Прилепване към ръбовете</translation>
    </message>
    <message>
        <source>Snap the stroke to the picture&apos;s edges</source>
        <translation>Прилепване на щриха към ръбовете на изображението</translation>
    </message>
    <message>
        <source>Find the sheet</source>
        <translation>Намери листа</translation>
    </message>
    <message>
        <source>Find the sheet in the background image</source>
        <translation>Намери листа във фоновото изображение</translation>
    </message>
    <message>
        <source>Estimated error at the far side: %1 mm</source>
        <translation>Оценена грешка в далечния край: %1 мм</translation>
    </message>
    <message>
        <source>Knots in the last outline: %1</source>
        <translation>Възли в последния контур: %1</translation>
    </message>
    <message>
        <source>in effect at this zoom: %1</source>
        <extracomment>%1 is the freehand tolerance that applies at the current zoom, with its unit (0,50 mm).</extracomment>
        <translation>в сила при този мащаб: %1</translation>
    </message>
</context>
<context>
    <name>TraceOverlay</name>
    <message>
        <source>seam %1</source>
        <extracomment>Label on the canvas: %1 is the seam length with its unit, for example “412,50 mm”.</extracomment>
        <translation>шев %1</translation>
    </message>
    <message>
        <source>max %1</source>
        <extracomment>Label on the canvas: the largest deviation from the reference curve, %1 a length with its unit.</extracomment>
        <translation>макс. %1</translation>
    </message>
    <message>
        <source>%1 px on the picture</source>
        <extracomment>%1 is a distance in pixels of the background picture (a number).</extracomment>
        <translation>%1 px върху изображението</translation>
    </message>
</context>
<context>
    <name>UnitsDialog</name>
    <message>
        <source>Units of the drawing</source>
        <translation>Мерни единици на чертежа</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отказ</translation>
    </message>
    <message>
        <source>“%1” does not say which units its numbers are in. Read them as (asked once for such files):</source>
        <translation>„%1“ не посочва в какви мерни единици са числата му. Да се четат като (пита се веднъж за такива файлове):</translation>
    </message>
    <message>
        <source>Read DXF files that do not say which units their numbers are in as:</source>
        <translation>DXF файловете, които не посочват в какви мерни единици са числата им, да се четат като:</translation>
    </message>
</context>
<context>
    <name>cli</name>
    <message>
        <source>Kontur: construct, modify and compare Bézier curves and splines.</source>
        <translation>Kontur: построяване, промяна и сравняване на криви на Безие и сплайни.</translation>
    </message>
    <message>
        <source>Language of the user interface: %1.</source>
        <translation>Език на потребителския интерфейс: %1.</translation>
    </message>
    <message>
        <source>A Kontur document to open.</source>
        <translation>Документ на Kontur за отваряне.</translation>
    </message>
    <message>
        <source>kontur: give at most one file to open.</source>
        <translation>kontur: посочете най-много един файл за отваряне.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: no such file.</source>
        <translation>kontur: не може да се отвори „%1“: няма такъв файл.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: its symbolic links form a loop.</source>
        <translation>kontur: не може да се отвори „%1“: символните му връзки образуват цикъл.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: permission denied.</source>
        <translation>kontur: не може да се отвори „%1“: достъпът е отказан.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: it is a folder, not a file.</source>
        <translation>kontur: не може да се отвори „%1“: това е папка, а не файл.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: it is not a regular file (a named pipe or a device).</source>
        <translation>kontur: не може да се отвори „%1“: това не е обикновен файл (а именуван канал или устройство).</translation>
    </message>
</context>
<context>
    <name>errors</name>
    <message>
        <source>the file does not exist or cannot be read.</source>
        <translation>файлът не съществува или не може да бъде прочетен.</translation>
    </message>
    <message>
        <source>the file cannot be written there (a folder that is missing or read-only, or a full disk).</source>
        <translation>файлът не може да бъде записан там (папката липсва или е само за четене, или дискът е пълен).</translation>
    </message>
    <message>
        <source>the file is larger than Kontur reads (%1 MB).</source>
        <extracomment>%1 is a size in megabytes, e.g. &quot;1 000&quot;.</extracomment>
        <translation>файлът е по-голям, отколкото Kontur може да прочете (%1 МБ).</translation>
    </message>
    <message>
        <source>the file holds more points than Kontur reads (%1).</source>
        <extracomment>%1 is a large number of points, e.g. &quot;6 000 000&quot;.</extracomment>
        <translation>файлът съдържа повече точки, отколкото Kontur може да прочете (%1).</translation>
    </message>
    <message>
        <source>the file holds more curves than Kontur reads (%1).</source>
        <translation>файлът съдържа повече криви, отколкото Kontur може да прочете (%1).</translation>
    </message>
    <message>
        <source>the file&apos;s structure is nested deeper than %1 levels.</source>
        <extracomment>The file&apos;s elements (JSON or XML) are nested inside each other deeper than %1 levels.</extracomment>
        <translation>структурата на файла е вложена на повече от %1 нива.</translation>
    </message>
    <message>
        <source>the file is not text in UTF-8.</source>
        <extracomment>UTF-8 is the name of a text encoding; keep it as it is.</extracomment>
        <translation>файлът не е текст в кодиране UTF-8.</translation>
    </message>
    <message>
        <source>a number was expected here.</source>
        <translation>тук се очакваше число.</translation>
    </message>
    <message>
        <source>this number is too large for Kontur, or is not a number.</source>
        <translation>това число е твърде голямо за Kontur или не е число.</translation>
    </message>
    <message>
        <source>more than a point on this line; in files, numbers are written with a decimal point.</source>
        <extracomment>Shown for &quot;1,5 2,5&quot; in a file: files write numbers with a decimal point.</extracomment>
        <translation>на реда има повече от една точка; във файловете числата се пишат с десетична точка.</translation>
    </message>
    <message>
        <source>a word Kontur does not know at the start of this line.</source>
        <translation>в началото на реда има дума, която Kontur не познава.</translation>
    </message>
    <message>
        <source>this line names a setting but gives no value.</source>
        <translation>редът посочва настройка, но без стойност.</translation>
    </message>
    <message>
        <source>a text in quotation marks is not closed.</source>
        <translation>текст в кавички не е затворен.</translation>
    </message>
    <message>
        <source>a curve without points.</source>
        <translation>крива без точки.</translation>
    </message>
    <message>
        <source>the file holds no points.</source>
        <translation>файлът не съдържа точки.</translation>
    </message>
    <message>
        <source>the first row must be the header “x,y”.</source>
        <extracomment>&quot;x,y&quot; is the first line of the file as it must be written; keep it as it is.</extracomment>
        <translation>първият ред трябва да е заглавието „x,y“.</translation>
    </message>
    <message>
        <source>each row must hold exactly two values, x and y.</source>
        <translation>всеки ред трябва да съдържа точно две стойности, x и y.</translation>
    </message>
    <message>
        <source>a kind of curve this version of Kontur does not know.</source>
        <translation>вид крива, който тази версия на Kontur не познава.</translation>
    </message>
    <message>
        <source>a parameterization this version of Kontur does not know.</source>
        <translation>параметризация, която тази версия на Kontur не познава.</translation>
    </message>
    <message>
        <source>a kind of knot this version of Kontur does not know.</source>
        <translation>вид възел, който тази версия на Kontur не познава.</translation>
    </message>
    <message>
        <source>the points must be knots or control points.</source>
        <translation>точките трябва да са възли или контролни точки.</translation>
    </message>
    <message>
        <source>too few or too many points for this kind of curve.</source>
        <translation>твърде малко или твърде много точки за този вид крива.</translation>
    </message>
    <message>
        <source>these points do not suit this kind of curve (knots where control points belong, or the reverse).</source>
        <translation>тези точки не подхождат на този вид крива (възли вместо контролни точки или обратно).</translation>
    </message>
    <message>
        <source>a value outside its range.</source>
        <translation>стойност извън допустимия диапазон.</translation>
    </message>
    <message>
        <source>the document is damaged: it is not well-formed JSON.</source>
        <translation>документът е повреден: не е валиден JSON.</translation>
    </message>
    <message>
        <source>this is not a Kontur document.</source>
        <translation>това не е документ на Kontur.</translation>
    </message>
    <message>
        <source>the document was written by a newer version of Kontur.</source>
        <translation>документът е записан от по-нова версия на Kontur.</translation>
    </message>
    <message>
        <source>a value the document needs is missing.</source>
        <translation>липсва стойност, която е нужна на документа.</translation>
    </message>
    <message>
        <source>a value of the wrong type (a number, a text or a list where another belongs).</source>
        <translation>стойност от грешен тип (число, текст или списък там, където трябва да има друг тип).</translation>
    </message>
    <message>
        <source>the file is damaged: it is not well-formed XML.</source>
        <translation>файлът е повреден: не е валиден XML.</translation>
    </message>
    <message>
        <source>this is not an SVG drawing.</source>
        <translation>това не е SVG чертеж.</translation>
    </message>
    <message>
        <source>the outline of a shape (its path data) is malformed.</source>
        <translation>контурът на фигура (данните на пътя ѝ) е неправилен.</translation>
    </message>
    <message>
        <source>a transformation of a shape is malformed.</source>
        <translation>трансформацията на фигура е неправилна.</translation>
    </message>
    <message>
        <source>the drawing holds no shapes Kontur can draw.</source>
        <translation>чертежът не съдържа фигури, които Kontur може да начертае.</translation>
    </message>
    <message>
        <source>this PDF was not printed by Kontur, so it holds no drawing Kontur can open. Open the .kontur document it came from.</source>
        <translation>този PDF не е отпечатан от Kontur и не съдържа чертеж, който Kontur може да отвори. Отворете документа .kontur, от който е създаден.</translation>
    </message>
    <message>
        <source>the DXF file is damaged or cut short.</source>
        <translation>DXF файлът е повреден или непълен.</translation>
    </message>
    <message>
        <source>the DXF file holds something Kontur cannot read (a binary DXF, or a shape off the drawing plane).</source>
        <translation>DXF файлът съдържа нещо, което Kontur не може да прочете (двоичен DXF или фигура извън равнината на чертежа).</translation>
    </message>
    <message>
        <source>this kind of curve cannot be written in this format.</source>
        <translation>този вид крива не може да бъде записан в този формат.</translation>
    </message>
    <message>
        <source>too few points for this kind of curve.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>твърде малко точки за този вид крива.</translation>
    </message>
    <message>
        <source>its knots need at least 4 different positions.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>възлите ѝ трябва да заемат поне 4 различни положения.</translation>
    </message>
    <message>
        <source>its knots lie too close together to define a curve.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>възлите ѝ са твърде близо един до друг, за да определят крива.</translation>
    </message>
    <message>
        <source>a coordinate is too large for Kontur, or is not a number.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>координата е твърде голяма за Kontur или не е число.</translation>
    </message>
    <message>
        <source>its values do not define a curve of its kind.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>стойностите ѝ не определят крива от нейния вид.</translation>
    </message>
    <message>
        <source>a value out of all proportion to the curve&apos;s size.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>стойност, несъразмерна с размера на кривата.</translation>
    </message>
    <message>
        <source>it would take more work than Kontur allows for one curve.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>това би изисквало повече работа, отколкото Kontur позволява за една крива.</translation>
    </message>
    <message>
        <source>the work was cancelled.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>работата беше отменена.</translation>
    </message>
    <message>
        <source>line %1, column %2: %3</source>
        <extracomment>Where in a file: %1 the line, %2 the column (character) in it, %3 what is wrong there.</extracomment>
        <translation>ред %1, колона %2: %3</translation>
    </message>
    <message>
        <source>line %1: %2</source>
        <extracomment>Where in a file: %1 the line, %2 what is wrong there.</extracomment>
        <translation>ред %1: %2</translation>
    </message>
    <message>
        <source>at %1: %2</source>
        <extracomment>Where in a document: %1 is the place as the file writes it (e.g. curves[3].points[7]), %2 what is wrong.</extracomment>
        <translation>в елемента %1: %2</translation>
    </message>
    <message>
        <source>curve %1: %2</source>
        <extracomment>%1 is the curve&apos;s number in the file (1, 2, …), %2 what is wrong with it.</extracomment>
        <translation>крива %1: %2</translation>
    </message>
    <message>
        <source>the points do not define a curve (two knots at the same place, or too few different knots).</source>
        <translation>точките не определят крива (два възела на едно място или твърде малко различни възли).</translation>
    </message>
    <message>
        <source>all its points are at the same place.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>всичките ѝ точки са на едно и също място.</translation>
    </message>
    <message>
        <source>two consecutive knots are at the same place.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>два последователни възела са на едно място.</translation>
    </message>
</context>
<context>
    <name>io</name>
    <message>
        <source>Outline %1</source>
        <extracomment>Automatic name of a curve traced along a piece&apos;s outline in the photo: %1 is a running number.</extracomment>
        <translation>Контур %1</translation>
    </message>
</context>
<context>
    <name>kontur</name>
    <message>
        <source>Add %1</source>
        <extracomment>Undo text: %1 is the name of the added curve.</extracomment>
        <translation>Добавяне на %1</translation>
    </message>
    <message>
        <source>Move point</source>
        <translation>Преместване на точка</translation>
    </message>
    <message>
        <source>Bézier curve</source>
        <translation>Крива на Безие</translation>
    </message>
    <message>
        <source>Bézier %1</source>
        <extracomment>Automatic name of a new curve: %1 is a running number (Bézier 3).</extracomment>
        <translation>Безие %1</translation>
    </message>
    <message>
        <source>Delete %1</source>
        <extracomment>Undo text: %1 is the name of the deleted curve.</extracomment>
        <translation>Изтриване на %1</translation>
    </message>
    <message>
        <source>Reorder curves</source>
        <translation>Пренареждане на кривите</translation>
    </message>
    <message>
        <source>Change background</source>
        <translation>Промяна на фоновото изображение</translation>
    </message>
    <message>
        <source>Cubic through 4 points</source>
        <translation>Кубична крива през 4 точки</translation>
    </message>
    <message>
        <source>Least-squares cubic</source>
        <translation>Кубична крива по метода на най-малките квадрати</translation>
    </message>
    <message>
        <source>Composite curve</source>
        <translation>Съставна крива</translation>
    </message>
    <message>
        <source>Through 4 points %1</source>
        <extracomment>Automatic name of a new cubic through 4 points: %1 is a running number.</extracomment>
        <translation>През 4 точки %1</translation>
    </message>
    <message>
        <source>Least squares %1</source>
        <extracomment>Automatic name of a new least-squares cubic: %1 is a running number.</extracomment>
        <translation>Най-малки квадрати %1</translation>
    </message>
    <message>
        <source>Composite %1</source>
        <extracomment>Automatic name of a new composite curve: %1 is a running number.</extracomment>
        <translation>Съставна %1</translation>
    </message>
    <message>
        <source>Change parameterization</source>
        <translation>Промяна на параметризацията</translation>
    </message>
    <message>
        <source>Rename curve</source>
        <translation>Преименуване на кривата</translation>
    </message>
    <message>
        <source>Change colour</source>
        <translation>Промяна на цвета</translation>
    </message>
    <message>
        <source>Show curve</source>
        <translation>Показване на кривата</translation>
    </message>
    <message>
        <source>Hide curve</source>
        <translation>Скриване на кривата</translation>
    </message>
    <message>
        <source>Lock curve</source>
        <translation>Заключване на кривата</translation>
    </message>
    <message>
        <source>Unlock curve</source>
        <translation>Отключване на кривата</translation>
    </message>
    <message>
        <source>Change node type</source>
        <translation>Промяна на вида на възела</translation>
    </message>
    <message>
        <source>Add point</source>
        <translation>Добавяне на точка</translation>
    </message>
    <message>
        <source>Delete point</source>
        <translation>Изтриване на точка</translation>
    </message>
    <message>
        <source>Insert knot</source>
        <translation>Вмъкване на възел</translation>
    </message>
    <message>
        <source>Close curve</source>
        <translation>Затваряне на кривата</translation>
    </message>
    <message>
        <source>Edit coordinates</source>
        <translation>Редактиране на координатите</translation>
    </message>
    <message>
        <source>Reset all</source>
        <translation>Изчистване на всичко</translation>
    </message>
    <message>
        <source>Natural spline</source>
        <translation>Естествен сплайн</translation>
    </message>
    <message>
        <source>Clamped spline</source>
        <extracomment>Curve kind: the cubic spline with given first derivatives at both ends (a complete or clamped spline).</extracomment>
        <translation>Закрепен сплайн</translation>
    </message>
    <message>
        <source>Not-a-knot spline</source>
        <extracomment>Curve kind: the cubic spline whose second and next-to-last knots are not knots (the third derivative is continuous there).</extracomment>
        <translation>Сплайн с условие „без възел“ (not-a-knot)</translation>
    </message>
    <message>
        <source>Periodic spline</source>
        <translation>Периодичен сплайн</translation>
    </message>
    <message>
        <source>Catmull–Rom spline</source>
        <translation>Сплайн на Катмъл–Ром</translation>
    </message>
    <message>
        <source>Hermite spline</source>
        <translation>Сплайн на Ермит</translation>
    </message>
    <message>
        <source>B-spline</source>
        <translation>B-сплайн</translation>
    </message>
    <message>
        <source>Global B-spline</source>
        <translation>Глобален B-сплайн</translation>
    </message>
    <message>
        <source>Interpolating polynomial</source>
        <translation>Интерполационен полином</translation>
    </message>
    <message>
        <source>Function spline y(x)</source>
        <translation>Сплайн-функция y(x)</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <extracomment>Automatic name of a new curve: %1 is its kind (“Natural spline”), %2 a running number.</extracomment>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>Change order</source>
        <translation>Промяна на реда на сплайна</translation>
    </message>
    <message>
        <source>Untitled</source>
        <extracomment>The name of a document that has not been saved yet (also the suggested file name).</extracomment>
        <translation>Без име</translation>
    </message>
    <message>
        <source>Import %1</source>
        <extracomment>Undo text: %1 is the name of the imported file.</extracomment>
        <translation>Импортиране на %1</translation>
    </message>
    <message>
        <source>Split curve</source>
        <translation>Разделяне на кривата</translation>
    </message>
    <message>
        <source>uniform</source>
        <extracomment>Parameterization name in lower case, shown after a kind name (“Natural spline, uniform”).</extracomment>
        <translation>равномерна</translation>
    </message>
    <message>
        <source>chord length</source>
        <extracomment>Parameterization name in lower case, shown after a kind name (“Natural spline, chord length”).</extracomment>
        <translation>по дължина на хордите</translation>
    </message>
    <message>
        <source>centripetal</source>
        <extracomment>Parameterization name in lower case, shown after a kind name (“Natural spline, centripetal”).</extracomment>
        <translation>центростремителна</translation>
    </message>
    <message>
        <source>Reduce degree</source>
        <translation>Понижаване на степента</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <extracomment>Legend in the Compare view: %1 is a curve kind, %2 a parameterization (“Natural spline, uniform”).</extracomment>
        <translation>%1, %2</translation>
    </message>
    <message>
        <source>Contour curve (midpoint joins)</source>
        <extracomment>Curve kind: quadratic Bézier pieces through the midpoints of the polygon&apos;s sides, joined smoothly there.</extracomment>
        <translation>Контурна крива (съединения в средите)</translation>
    </message>
    <message>
        <source>Nothing to print: no curve is visible.</source>
        <translation>Няма какво да се отпечата: няма видима крива.</translation>
    </message>
    <message>
        <source>The drawing would need more than %1 pages at true size. Check the document&apos;s units.</source>
        <translation>В действителен размер чертежът би заел повече от %1 страници. Проверете мерните единици на документа.</translation>
    </message>
    <message>
        <source>The drawing cannot be printed: %1</source>
        <translation>Чертежът не може да бъде отпечатан: %1</translation>
    </message>
    <message>
        <source>%1 seam allowance</source>
        <extracomment>Name of a new seam allowance: %1 is the name of its curve.</extracomment>
        <translation>%1 – добавка за шев</translation>
    </message>
    <message>
        <source>Add seam allowance</source>
        <translation>Създаване на добавка за шев</translation>
    </message>
    <message>
        <source>Change seam allowance</source>
        <translation>Промяна на добавката за шев</translation>
    </message>
    <message>
        <source>Detach seam allowance</source>
        <translation>Отделяне на добавката за шев</translation>
    </message>
    <message>
        <source>no file name was given</source>
        <translation>не е зададено име на файл</translation>
    </message>
</context>
<context>
    <name>kontur::FunctionSplinePlot</name>
    <message>
        <source>Function values: “%1” is not a number.</source>
        <translation>Стойности на функцията: „%1“ не е число.</translation>
    </message>
    <message>
        <source>Function values: give between 2 and %1 numbers.</source>
        <translation>Стойности на функцията: въведете от 2 до %1 числа.</translation>
    </message>
    <message>
        <source>Interval: “%1” is not a number.</source>
        <translation>Интервал: „%1“ не е число.</translation>
    </message>
    <message>
        <source>Interval: give two numbers, the smaller first.</source>
        <translation>Интервал: въведете две числа, първо по-малкото.</translation>
    </message>
    <message>
        <source>Knots: “%1” is not a number.</source>
        <translation>Възли: „%1“ не е число.</translation>
    </message>
    <message numerus="yes">
        <source>Knots: give %n number(s), one per function value.</source>
        <translation>
            <numerusform>Възли: въведете %n число, по едно за всяка стойност на функцията.</numerusform>
            <numerusform>Възли: въведете %n числа, по едно за всяка стойност на функцията.</numerusform>
        </translation>
    </message>
    <message>
        <source>Knots: each knot must be greater than the one before.</source>
        <translation>Възли: всеки възел трябва да е по-голям от предишния.</translation>
    </message>
    <message>
        <source>Derivatives: “%1” is not a number.</source>
        <translation>Производни: „%1“ не е число.</translation>
    </message>
    <message numerus="yes">
        <source>Derivatives: give %n number(s), one per knot.</source>
        <translation>
            <numerusform>Производни: въведете %n число, по едно за всеки възел.</numerusform>
            <numerusform>Производни: въведете %n числа, по едно за всеки възел.</numerusform>
        </translation>
    </message>
    <message>
        <source>Derivatives: give two numbers, at the first and the last knot.</source>
        <translation>Производни: въведете две числа, в първия и в последния възел.</translation>
    </message>
    <message>
        <source>Values P at the inner knots: %1</source>
        <translation>Стойности P във вътрешните възли: %1</translation>
    </message>
    <message>
        <source>Slopes y′ at the knots: %1</source>
        <translation>Наклони y′ във възлите: %1</translation>
    </message>
    <message>
        <source>Polynomial of degree %1: it differs from the spline by up to %2.</source>
        <translation>Полином от степен %1: отклонява се от сплайна с най-много %2.</translation>
    </message>
    <message numerus="yes">
        <source>The polynomial is drawn for at most %n point(s).</source>
        <translation>
            <numerusform>Полиномът се чертае за най-много %n точка.</numerusform>
            <numerusform>Полиномът се чертае за най-много %n точки.</numerusform>
        </translation>
    </message>
    <message>
        <source>polynomial</source>
        <extracomment>Legend label (noun): the interpolating polynomial drawn beside the spline.</extracomment>
        <translation>полином</translation>
    </message>
    <message>
        <source>spline</source>
        <extracomment>Legend label (noun): the spline.</extracomment>
        <translation>сплайн</translation>
    </message>
    <message>
        <source>Török&apos;s procedure needs evenly spaced knots: the classical system is drawn.</source>
        <translation>Методът на Тьорьок изисква равномерно разположени възли: начертано е решението на класическата система.</translation>
    </message>
    <message>
        <source>Török&apos;s half-size system and the classical system agree: their slopes differ by at most %1.</source>
        <translation>Системата на Тьорьок с половин размер и класическата система съвпадат: производните им се различават най-много с %1.</translation>
    </message>
    <message>
        <source>Add the function spline to the document</source>
        <translation>Добавяне на сплайн-функцията към документа</translation>
    </message>
    <message numerus="yes">
        <source>Knots: give %n number(s), four more than the number of values.</source>
        <translation>
            <numerusform>Възли: въведете %n число, с четири повече от броя на стойностите.</numerusform>
            <numerusform>Възли: въведете %n числа, с четири повече от броя на стойностите.</numerusform>
        </translation>
    </message>
    <message>
        <source>Control values b: %1</source>
        <extracomment>b are the global B-spline&apos;s control values, as the course writes them (one per bell Bs).</extracomment>
        <translation>Контролни стойности b: %1</translation>
    </message>
    <message>
        <source>Török&apos;s half-size system and the classical system agree: their slopes differ by less than 10⁻¹⁵ (rounding).</source>
        <translation>Системата на Тьорьок с половин размер и класическата система съвпадат: производните им се различават с по-малко от 10⁻¹⁵ (закръгляне).</translation>
    </message>
    <message>
        <source>P(%1) = %2</source>
        <extracomment>One value of the spline: P(1,5) = 0,075 (%1 is x, %2 the value).</extracomment>
        <translation>P(%1) = %2</translation>
    </message>
    <message>
        <source>Between the knots: %1</source>
        <extracomment>The spline&apos;s values halfway between the knots, e.g. &quot;P(1,5) = 0,075; P(2,5) = 1,175&quot;.</extracomment>
        <translation>Между възлите: %1</translation>
    </message>
</context>
<context>
    <name>kontur::PieceEdits</name>
    <message>
        <source>There is no other open composite curve to join.</source>
        <translation>Няма друга отворена съставна крива за съединяване.</translation>
    </message>
    <message>
        <source>No curve with fewer knots stays within that tolerance.</source>
        <translation>Никоя крива с по-малко възли не остава в този допуск.</translation>
    </message>
    <message>
        <source>Type a tolerance greater than zero.</source>
        <translation>Въведете допуск, по-голям от нула.</translation>
    </message>
    <message>
        <source>This works on composite curves that are not locked.</source>
        <translation>Това работи със съставни криви, които не са заключени.</translation>
    </message>
    <message>
        <source>Make line</source>
        <translation>Изправяне на сегмента</translation>
    </message>
    <message>
        <source>Join curves</source>
        <translation>Съединяване на криви</translation>
    </message>
    <message>
        <source>Simplify curve</source>
        <translation>Опростяване на кривата</translation>
    </message>
    <message>
        <source>Extend curve</source>
        <translation>Продължаване на кривата</translation>
    </message>
</context>
<context>
    <name>kontur::PieceMarkEdits</name>
    <message>
        <source>A pattern piece is a closed curve: close the curve first.</source>
        <translation>Детайлът от кройката е затворена крива: първо затворете кривата.</translation>
    </message>
    <message>
        <source>Select a pattern piece first.</source>
        <translation>Първо изберете детайл от кройката.</translation>
    </message>
    <message>
        <source>Type how many to cut: a whole number from 1 up.</source>
        <translation>Въведете колко да се скроят: цяло число от 1 нагоре.</translation>
    </message>
    <message>
        <source>The two points are too close together: tap two points farther apart.</source>
        <translation>Двете точки са твърде близо: докоснете две по-отдалечени точки.</translation>
    </message>
    <message>
        <source>There is no mark there.</source>
        <translation>Там няма знак.</translation>
    </message>
    <message>
        <source>Make a pattern piece</source>
        <translation>Направи детайл от кройката</translation>
    </message>
    <message>
        <source>No longer a pattern piece</source>
        <translation>Вече не е детайл от кройката</translation>
    </message>
    <message>
        <source>Set the piece&apos;s size</source>
        <translation>Задай размера на детайла</translation>
    </message>
    <message>
        <source>Set how many to cut</source>
        <translation>Задай колко да се скроят</translation>
    </message>
    <message>
        <source>Set the piece&apos;s material</source>
        <translation>Задай материала на детайла</translation>
    </message>
    <message>
        <source>Draw the grainline</source>
        <translation>Начертай посоката на основата</translation>
    </message>
    <message>
        <source>Place on fold</source>
        <translation>Постави на сгъвка</translation>
    </message>
    <message>
        <source>Add a notch</source>
        <translation>Добави засечка</translation>
    </message>
    <message>
        <source>Move a notch</source>
        <translation>Премести засечка</translation>
    </message>
    <message>
        <source>Change a notch</source>
        <translation>Промени засечка</translation>
    </message>
    <message>
        <source>Add a drill hole</source>
        <translation>Добави пробив</translation>
    </message>
    <message>
        <source>Move a drill hole</source>
        <translation>Премести пробив</translation>
    </message>
    <message>
        <source>Delete a mark</source>
        <translation>Изтрий знак</translation>
    </message>
</context>
<context>
    <name>kontur::PracticumPlot</name>
    <message>
        <source>The end points have the same x: there is no function segment.</source>
        <translation>Крайните точки имат еднакво x: няма функционален сегмент.</translation>
    </message>
    <message>
        <source>A vertical guide vector has no slope dy/dx: a function segment needs one.</source>
        <translation>Вертикален направляващ вектор няма наклон dy/dx: функционалният сегмент се нуждае от него.</translation>
    </message>
    <message>
        <source>t = x1 − x0 = %1; k0 = %2; k1 = %3; a3 = %4; a4 = %5</source>
        <translation>t = x1 − x0 = %1; k0 = %2; k1 = %3; a3 = %4; a4 = %5</translation>
    </message>
    <message>
        <source>The end points coincide or a guide vector has no length.</source>
        <translation>Крайните точки съвпадат или направляващ вектор е с нулева дължина.</translation>
    </message>
    <message>
        <source>t2 = |P1 − P0| = %1; P0′ = %2; P1′ = %3; a3 = %4; a4 = %5</source>
        <translation>t2 = |P1 − P0| = %1; P0′ = %2; P1′ = %3; a3 = %4; a4 = %5</translation>
    </message>
    <message>
        <source>Two neighbouring points coincide or a guide vector has no length.</source>
        <translation>Две съседни точки съвпадат или направляващ вектор е с нулева дължина.</translation>
    </message>
    <message>
        <source>Chords T: %1
Tangents K: %2</source>
        <extracomment>Two lines of figures: %1 the chord lengths T, %2 the tangent lengths K of the segments (numbers).</extracomment>
        <translation>Хорди T: %1
Допирателни K: %2</translation>
    </message>
</context>
<context>
    <name>kontur::SeamWidths</name>
    <message>
        <source>The piece has no seam allowance yet: add one first.</source>
        <translation>Детайлът още няма добавка за шев: първо добавете такава.</translation>
    </message>
    <message>
        <source>Tap a seam of the piece first.</source>
        <translation>Първо докоснете шев на детайла.</translation>
    </message>
    <message>
        <source>Type the seam allowance: a number from 0 up.</source>
        <translation>Въведете добавката за шев: число от 0 нагоре.</translation>
    </message>
    <message>
        <source>The seam allowance cannot be that wide on this piece.</source>
        <translation>Добавката за шев не може да е толкова широка за този детайл.</translation>
    </message>
    <message>
        <source>Set a seam&apos;s allowance</source>
        <translation>Задаване на добавка за шев</translation>
    </message>
    <message>
        <source>Set a hem&apos;s corners</source>
        <translation>Задаване на ъглите на подгъва</translation>
    </message>
</context>
<context>
    <name>kontur::TraceController</name>
    <message>
        <source>Calibrate background</source>
        <translation>Калибриране на фона</translation>
    </message>
    <message>
        <source>The tolerance must be a positive number.</source>
        <translation>Допускът трябва да е положително число.</translation>
    </message>
    <message>
        <source>Draw along the contour with one finger, a stylus or the mouse.</source>
        <translation>Чертайте по контура с един пръст, писалка или мишка.</translation>
    </message>
    <message>
        <source>The stroke could not be fitted.</source>
        <translation>Щрихът не може да бъде апроксимиран.</translation>
    </message>
    <message>
        <source>Traced %1</source>
        <extracomment>Automatic name of a curve drawn freehand over the picture: %1 is a running number.</extracomment>
        <translation>Очертана %1</translation>
    </message>
    <message>
        <source>Freehand curve</source>
        <translation>Крива, начертана от ръка</translation>
    </message>
    <message>
        <source>Load a background picture first.</source>
        <translation>Първо заредете фоново изображение.</translation>
    </message>
    <message>
        <source>Tap a knot of the curve.</source>
        <translation>Докоснете възел на кривата.</translation>
    </message>
    <message>
        <source>Tap a curve.</source>
        <translation>Докоснете крива.</translation>
    </message>
    <message>
        <source>Tap a second, different curve.</source>
        <translation>Докоснете втора, различна крива.</translation>
    </message>
    <message>
        <source>This kind of curve has no knots to measure between.</source>
        <translation>Този вид крива няма възли, между които да се мери.</translation>
    </message>
    <message>
        <source>These curves cannot be compared.</source>
        <translation>Тези криви не могат да бъдат сравнени.</translation>
    </message>
    <message>
        <source>Tap two points on the picture first.</source>
        <translation>Първо докоснете две точки върху изображението.</translation>
    </message>
    <message>
        <source>Type the real distance between the two points as a positive number.</source>
        <translation>Въведете реалното разстояние между двете точки като положително число.</translation>
    </message>
    <message>
        <source>The background is locked. Unlock it to calibrate again.</source>
        <translation>Фонът е заключен. Отключете го, за да калибрирате отново.</translation>
    </message>
    <message>
        <source>Choose mm, cm or in.</source>
        <translation>Изберете мм, см или инчове.</translation>
    </message>
    <message>
        <source>The two points must be different.</source>
        <translation>Двете точки трябва да са различни.</translation>
    </message>
    <message>
        <source>Curve &quot;%1&quot; cannot be turned; calibrate without aligning.</source>
        <translation>Кривата „%1“ не може да бъде завъртяна; калибрирайте без подравняване.</translation>
    </message>
    <message>
        <source>Draw along the contour with one finger, a stylus or the mouse; two fingers zoom.</source>
        <translation>Чертайте по контура с един пръст, писалка или мишка; с два пръста се мащабира.</translation>
    </message>
    <message>
        <source>Tap two points on the picture whose real distance you know.</source>
        <translation>Докоснете две точки от изображението, чието реално разстояние знаете.</translation>
    </message>
    <message>
        <source>Type the real distance between the two points.</source>
        <translation>Въведете реалното разстояние между двете точки.</translation>
    </message>
    <message>
        <source>Tap two points to measure the straight distance.</source>
        <translation>Докоснете две точки, за да измерите разстоянието по права.</translation>
    </message>
    <message>
        <source>Tap two knots of one curve to measure the length along it.</source>
        <translation>Докоснете два възела на една крива, за да измерите дължината по нея.</translation>
    </message>
    <message>
        <source>Tap the traced curve, then the reference curve.</source>
        <translation>Докоснете очертаната крива, след това еталонната.</translation>
    </message>
    <message>
        <source>Drag the picture to move it; two fingers zoom.</source>
        <translation>Плъзнете изображението, за да го преместите; с два пръста се мащабира.</translation>
    </message>
    <message>
        <source>The background is locked. Unlock it to move it.</source>
        <translation>Фонът е заключен. Отключете го, за да го преместите.</translation>
    </message>
    <message>
        <source>Tap the four corners of the rectangle first.</source>
        <translation>Първо докоснете четирите ъгъла на правоъгълника.</translation>
    </message>
    <message>
        <source>Type the rectangle&apos;s width and height as positive numbers.</source>
        <translation>Въведете ширината и височината на правоъгълника като положителни числа.</translation>
    </message>
    <message>
        <source>The picture has a perspective calibration. Clear it to calibrate by two points.</source>
        <translation>Изображението има калибриране на перспективата. Премахнете го, за да калибрирате по две точки.</translation>
    </message>
    <message>
        <source>There the corners would not make a rectangle; the corner stays where it was.</source>
        <translation>Там ъглите не биха образували правоъгълник; ъгълът остава на мястото си.</translation>
    </message>
    <message>
        <source>Drag a corner onto the rectangle&apos;s corner in the picture, or tap four new corners.</source>
        <translation>Плъзнете ъгъл върху ъгъла на правоъгълника в изображението или докоснете четири нови ъгъла.</translation>
    </message>
    <message>
        <source>Tap the four corners of a rectangle whose size you know, in any order.</source>
        <translation>Докоснете в произволен ред четирите ъгъла на правоъгълник, чиито размери знаете.</translation>
    </message>
    <message>
        <source>Choose the rectangle&apos;s size and apply; drag a corner to refine it.</source>
        <translation>Изберете размера на правоъгълника и го приложете; плъзнете ъгъл, за да го уточните.</translation>
    </message>
    <message>
        <source>Calibrate perspective</source>
        <translation>Калибриране на перспективата</translation>
    </message>
    <message>
        <source>Refine perspective corner</source>
        <translation>Уточняване на ъгъл на перспективата</translation>
    </message>
    <message>
        <source>Outline %1</source>
        <extracomment>Automatic name of a curve traced along a piece&apos;s outline in the photo: %1 is a running number.</extracomment>
        <translation>Контур %1</translation>
    </message>
    <message>
        <source>Trace outline</source>
        <translation>Обрисуване на контура</translation>
    </message>
    <message>
        <source>The background picture cannot be read.</source>
        <translation>Фоновото изображение не може да бъде прочетено.</translation>
    </message>
    <message>
        <source>No sheet found in the picture (a white rectangle with four straight, clear edges). Tap its four corners instead.</source>
        <translation>В изображението не е намерен лист (бял правоъгълник с четири прави, ясни ръба). Вместо това докоснете четирите му ъгъла.</translation>
    </message>
    <message>
        <source>No corner found near the mark; it stays where you dropped it.</source>
        <translation>Близо до маркера не е намерен ъгъл; той остава там, където го пуснахте.</translation>
    </message>
    <message>
        <source>The calibration may be off by %1 mm at the far side of the picture. Find the sheet again or refine its corners.</source>
        <translation>Калибрирането може да се отклонява с %1 мм в далечния край на изображението. Намерете листа отново или уточнете ъглите му.</translation>
    </message>
    <message>
        <source>No pattern piece found there. Tap inside a piece that stands out from the table.</source>
        <translation>Там не е намерен детайл от кройката. Докоснете вътре в детайл, който се отличава от масата.</translation>
    </message>
    <message>
        <source>The outline could not be made into a curve.</source>
        <translation>Контурът не може да бъде превърнат в крива.</translation>
    </message>
    <message>
        <source>No edge found along the stroke; it was fitted as drawn.</source>
        <translation>По протежение на щриха не е намерен ръб; той е апроксимиран както е начертан.</translation>
    </message>
    <message>
        <source>Tap inside a pattern piece on the picture to trace its outline.</source>
        <translation>Докоснете вътре в детайл от кройката в изображението за обрисуване на контура му.</translation>
    </message>
    <message>
        <source>The four points are not the corners of a rectangle seen in the picture. Tap them again.</source>
        <translation>Четирите точки не са ъгли на правоъгълник от изображението. Докоснете ги отново.</translation>
    </message>
    <message>
        <source>The sheet in the picture is not flat: its edges bend. Lay it flat and take the photo again, or tap its four corners.</source>
        <translation>Листът в изображението не е равен: ръбовете му са извити. Поставете го да лежи равно и го снимайте отново или докоснете четирите му ъгъла.</translation>
    </message>
    <message>
        <source>The rectangle found is about %1 : 1, the chosen one %2 : 1. Choose the sheet&apos;s size, or tap its four corners.</source>
        <extracomment>%1 and %2 are proportions, long side to short side, such as 2.35 and 1.41.</extracomment>
        <translation>Намереният правоъгълник е около %1 : 1, а избраният — %2 : 1. Изберете размера на листа или докоснете четирите му ъгъла.</translation>
    </message>
</context>
<context>
    <name>kontur::cli</name>
    <message>
        <source>%1: several curves in the file (%2); the points of the first one (line %3) are read</source>
        <translation>%1: файлът съдържа няколко криви (%2); четат се точките на първата (ред %3)</translation>
    </message>
    <message>
        <source>unexpected argument &quot;%1&quot;</source>
        <translation>неочакван аргумент „%1“</translation>
    </message>
    <message>
        <source>--in FILE is required</source>
        <translation>необходим е --in ФАЙЛ</translation>
    </message>
    <message>
        <source>Fit a cubic Bézier curve to points (one &quot;x y&quot; per line).</source>
        <translation>Приближава точки с кубична крива на Безие (по едно „x y“ на ред).</translation>
    </message>
    <message>
        <source>interpolate (exactly 4 points) or least-squares.</source>
        <translation>interpolate (точно 4 точки) или least-squares.</translation>
    </message>
    <message>
        <source>uniform, chord or centripetal.</source>
        <translation>uniform, chord или centripetal.</translation>
    </message>
    <message>
        <source>The points file.</source>
        <translation>Файлът с точки.</translation>
    </message>
    <message>
        <source>unknown --method &quot;%1&quot; (interpolate or least-squares)</source>
        <translation>непознат --method „%1“ (interpolate или least-squares)</translation>
    </message>
    <message>
        <source>unknown --param &quot;%1&quot; (uniform, chord or centripetal)</source>
        <translation>непознат --param „%1“ (uniform, chord или centripetal)</translation>
    </message>
    <message>
        <source>--reparameterize needs a non-negative integer</source>
        <translation>--reparameterize изисква неотрицателно цяло число</translation>
    </message>
    <message>
        <source>%1: %2 points; interpolate needs exactly 4</source>
        <extracomment>%1 is a file name, %2 the number of points in it.</extracomment>
        <translation>%1: %2 точки; interpolate изисква точно 4</translation>
    </message>
    <message>
        <source>The control points file.</source>
        <translation>Файлът с контролните точки.</translation>
    </message>
    <message>
        <source>Elevate the degree R times.</source>
        <translation>Увеличава степента R пъти.</translation>
    </message>
    <message>
        <source>Evaluate at t1,t2,…</source>
        <translation>Пресмята при t1,t2,…</translation>
    </message>
    <message>
        <source>Arc length to this absolute accuracy.</source>
        <translation>Дължина на дъгата с тази абсолютна точност.</translation>
    </message>
    <message>
        <source>Nearest point to x,y.</source>
        <translation>Най-близката точка до x,y.</translation>
    </message>
    <message>
        <source>The tight bounding box.</source>
        <translation>Точният обхващащ правоъгълник.</translation>
    </message>
    <message>
        <source>--elevate needs an integer from 0 to 10000</source>
        <translation>--elevate изисква цяло число от 0 до 10000</translation>
    </message>
    <message>
        <source>--at needs numbers separated by commas</source>
        <translation>--at изисква числа, разделени със запетаи</translation>
    </message>
    <message>
        <source>--length needs a positive accuracy</source>
        <translation>--length изисква положителна точност</translation>
    </message>
    <message>
        <source>--nearest needs x,y</source>
        <translation>--nearest изисква x,y</translation>
    </message>
    <message>
        <source>Build the composite curve through the knots in the file.</source>
        <translation>Построява съставната крива през възлите от файла.</translation>
    </message>
    <message>
        <source>The knots file.</source>
        <translation>Файлът с възлите.</translation>
    </message>
    <message>
        <source>Close the curve.</source>
        <translation>Затваря кривата.</translation>
    </message>
    <message>
        <source>Relative tolerance of the continuity report (default 1e-9).</source>
        <translation>Относителен допуск на отчета за непрекъснатост (по подразбиране 1e-9).</translation>
    </message>
    <message>
        <source>--tolerance needs a non-negative number</source>
        <translation>--tolerance изисква неотрицателно число</translation>
    </message>
    <message numerus="yes">
        <source>expected %n file name(s), got %1</source>
        <translation>
            <numerusform>очаквано %n име на файл, получени %1</numerusform>
            <numerusform>очаквани %n имена на файлове, получени %1</numerusform>
        </translation>
    </message>
    <message>
        <source>The input file.</source>
        <translation>Входният файл.</translation>
    </message>
    <message>
        <source>The output file.</source>
        <translation>Изходният файл.</translation>
    </message>
    <message>
        <source>Kind of curve for points without one (default composite).</source>
        <translation>Вид крива за точки без зададен вид (по подразбиране composite).</translation>
    </message>
    <message>
        <source>Parameterization for fitted kinds (default chord).</source>
        <translation>Параметризация за приближаваните видове (по подразбиране chord).</translation>
    </message>
    <message>
        <source>Write only curve N (0-based).</source>
        <translation>Записва само крива N (от 0).</translation>
    </message>
    <message>
        <source>unknown --kind &quot;%1&quot;</source>
        <translation>непознат --kind „%1“</translation>
    </message>
    <message>
        <source>--curve needs a curve number from 0 to %1</source>
        <translation>--curve изисква номер на крива от 0 до %1</translation>
    </message>
    <message>
        <source>Describe the curves of a file as JSON: kinds, point counts, lengths, bounding boxes, continuity.</source>
        <translation>Описва кривите на файл като JSON: видове, брой точки, дължини, обхващащи правоъгълници, непрекъснатост.</translation>
    </message>
    <message>
        <source>Absolute accuracy of the lengths (default 1e-9).</source>
        <translation>Абсолютна точност на дължините (по подразбиране 1e-9).</translation>
    </message>
    <message>
        <source>--accuracy needs a positive number</source>
        <translation>--accuracy изисква положително число</translation>
    </message>
    <message>
        <source>
For every command:
  --lang CODE  the language of help and messages: %1 (default: the system&apos;s)
</source>
        <translation>
За всички команди:
  --lang КОД   езикът на помощта и съобщенията: %1 (по подразбиране този на системата)
</translation>
    </message>
    <message>
        <source>kontur-cli: unknown command &quot;%1&quot;</source>
        <translation>kontur-cli: непозната команда „%1“</translation>
    </message>
    <message>
        <source>%1:%2: expected two numbers &quot;x y&quot;, got &quot;%3&quot;</source>
        <translation>%1:%2: очакват се две числа „x y“, получено „%3“</translation>
    </message>
    <message>
        <source>%1: cannot read the file: %2</source>
        <translation>%1: файлът не може да бъде прочетен: %2</translation>
    </message>
    <message>
        <source>The family (see above).</source>
        <translation>Семейството (вижте по-горе).</translation>
    </message>
    <message>
        <source>uniform, chord (default) or centripetal.</source>
        <translation>uniform, chord (по подразбиране) или centripetal.</translation>
    </message>
    <message>
        <source>A function spline y(x) over the points&apos; increasing x; --at then takes x values and points are [x, y].</source>
        <translation>Сплайн-функция y(x) над нарастващите x на точките; тогава --at приема стойности на x и точките са [x, y].</translation>
    </message>
    <message>
        <source>Start tangent x,y (clamped, global-bspline; default the first chord).</source>
        <translation>Начален направляващ вектор x,y (clamped, global-bspline; по подразбиране първата хорда).</translation>
    </message>
    <message>
        <source>End tangent x,y (clamped, global-bspline; default the last chord).</source>
        <translation>Краен направляващ вектор x,y (clamped, global-bspline; по подразбиране последната хорда).</translation>
    </message>
    <message>
        <source>--kind must be one of %1</source>
        <translation>--kind трябва да е един от %1</translation>
    </message>
    <message>
        <source>--%1 needs x,y</source>
        <translation>--%1 изисква x,y</translation>
    </message>
    <message>
        <source>--order needs an integer</source>
        <translation>--order изисква цяло число</translation>
    </message>
    <message>
        <source>a function B-spline takes a knot vector and control values, not points: drop --function</source>
        <translation>B-сплайн-функцията приема възлов вектор и контролни стойности, а не точки: премахнете --function</translation>
    </message>
    <message>
        <source>at least 2 points are needed</source>
        <translation>нужни са поне 2 точки</translation>
    </message>
    <message>
        <source>a vertical or zero end tangent has no slope</source>
        <translation>вертикален или нулев краен направляващ вектор няма наклон</translation>
    </message>
    <message>
        <source>--knots needs open-uniform, uniform or numbers separated by commas</source>
        <translation>--knots изисква open-uniform, uniform или числа, разделени със запетаи</translation>
    </message>
    <message>
        <source>could not compute &quot;%1&quot; as a finite number: the numbers involved exceed the range of double precision</source>
        <translation>„%1“ не може да се изчисли като крайно число: числата надхвърлят обхвата на двойната точност</translation>
    </message>
    <message>
        <source>unknown --solver &quot;%1&quot; (classical or torok)</source>
        <translation>непознат --solver „%1“ (classical или torok)</translation>
    </message>
    <message>
        <source>--solver is for --kind clamped</source>
        <translation>--solver е само за --kind clamped</translation>
    </message>
    <message>
        <source>Török&apos;s procedure needs evenly spaced knots: use --param uniform or --function</source>
        <translation>Методът на Тьорьок изисква равномерно разположени възли: използвайте --param uniform или --function</translation>
    </message>
    <message>
        <source>a contour curve is drawn through its points in the plane: drop --function</source>
        <translation>контурната крива се чертае по точки в равнината: премахнете --function</translation>
    </message>
    <message>
        <source>--paper needs a4 or letter</source>
        <translation>--paper изисква a4 или letter</translation>
    </message>
    <message>
        <source>--orientation needs auto, portrait or landscape</source>
        <translation>--orientation изисква auto, portrait или landscape</translation>
    </message>
    <message>
        <source>--overlap needs millimetres from 0 to 50</source>
        <translation>--overlap изисква милиметри от 0 до 50</translation>
    </message>
    <message>
        <source>PDF: the paper, a4 or letter (default a4).</source>
        <translation>PDF: хартията, a4 или letter (по подразбиране a4).</translation>
    </message>
    <message>
        <source>PDF: auto (the one with fewer pages), portrait or landscape (default auto).</source>
        <translation>PDF: auto (тази с по-малко страници), portrait или landscape (по подразбиране auto).</translation>
    </message>
    <message>
        <source>PDF: millimetres neighbouring pages repeat (default 10).</source>
        <translation>PDF: милиметри, които съседните страници повтарят (по подразбиране 10).</translation>
    </message>
    <message>
        <source>Add seam allowances: the offset of each curve (or of curve N) at a distance, written after the
input&apos;s curves. In a .kontur output each allowance keeps its link to its curve.</source>
        <translation>Създава добавки за шев: отместената крива на всяка крива (или на крива N) на дадено разстояние,
записана след кривите на входа. В изход .kontur всяка добавка запазва връзката с кривата си.</translation>
    </message>
    <message>
        <source>Offset only curve N (0-based).</source>
        <translation>Отместване само на крива N (от 0).</translation>
    </message>
    <message>
        <source>Distance in the document&apos;s units (default 1 cm).</source>
        <translation>Разстояние в мерните единици на документа (по подразбиране 1 см).</translation>
    </message>
    <message>
        <source>outside, inside, left or right (default outside).</source>
        <translation>outside, inside, left или right (по подразбиране outside).</translation>
    </message>
    <message>
        <source>Corners: miter, bevel or round (default miter).</source>
        <translation>Ъгли: miter, bevel или round (по подразбиране miter).</translation>
    </message>
    <message>
        <source>Longest miter from the corner (default 3 cm).</source>
        <translation>Най-голяма дължина на острия ъгъл от върха (по подразбиране 3 см).</translation>
    </message>
    <message>
        <source>Largest error of the offset (default 0.05 mm).</source>
        <translation>Най-голяма грешка на отместването (по подразбиране 0,05 мм).</translation>
    </message>
    <message>
        <source>--distance needs a positive number</source>
        <translation>--distance изисква положително число</translation>
    </message>
    <message>
        <source>--miter-limit needs a number of at least 0</source>
        <translation>--miter-limit изисква число, не по-малко от 0</translation>
    </message>
    <message>
        <source>--tolerance needs a positive number</source>
        <translation>--tolerance изисква положително число</translation>
    </message>
    <message>
        <source>unknown --side &quot;%1&quot;</source>
        <translation>непознат --side „%1“</translation>
    </message>
    <message>
        <source>unknown --join &quot;%1&quot;</source>
        <translation>непознат --join „%1“</translation>
    </message>
    <message>
        <source>%1: unknown file type (%2)</source>
        <translation>%1: непознат тип файл (%2)</translation>
    </message>
    <message>
        <source>Convert between points text (.txt), CSV, Kontur documents (.kontur), SVG and DXF, by extension.
A .txt output is appended to, never overwritten; other outputs are replaced atomically.
A .pdf output prints the visible curves at true size over A4 or Letter pages (a first page with
a 10 cm test square and the overview, then the pages to tape together); the document is kept
inside, so a PDF Kontur wrote converts back.</source>
        <translation>Преобразува между текст с точки (.txt), CSV, документи на Kontur (.kontur), SVG и DXF според разширението.
Изходът .txt се допълва, никога не се презаписва; другите изходи се заменят атомарно.
Изходът .pdf отпечатва видимите криви в действителен размер на страници A4 или Letter (първа страница с
контролен квадрат 10 см и общ изглед, после страниците за слепване); документът се съхранява вътре,
затова PDF, записан от Kontur, се преобразува обратно.</translation>
    </message>
    <message>
        <source>DXF output: spline (exact Bézier control points, default) or polyline (flattened).</source>
        <translation>Изход DXF: spline (сплайни с точните контролни точки на Безие, по подразбиране) или polyline (начупени линии).</translation>
    </message>
    <message>
        <source>DXF polyline output: largest distance from the curves, in the document&apos;s units (default 0.05 mm).</source>
        <translation>Изход DXF с начупени линии: най-голямото разстояние от кривите в единиците на документа (по подразбиране 0,05 мм).</translation>
    </message>
    <message>
        <source>unknown --dxf &quot;%1&quot; (spline or polyline)</source>
        <translation>непознат --dxf „%1“ (spline — сплайни, или polyline — начупени линии)</translation>
    </message>
    <message>
        <source>A .txt, .csv, .kontur, .svg or .dxf file.</source>
        <translation>Файл .txt, .csv, .kontur, .svg или .dxf.</translation>
    </message>
    <message>
        <source>The photo (PNG, JPEG, PGM, ...).</source>
        <translation>Снимката (PNG, JPEG, PGM, ...).</translation>
    </message>
    <message>
        <source>The sheet&apos;s size: a4, a3, letter or WxH with mm (default), cm or in.</source>
        <translation>Размерът на листа: a4, a3, letter или WxH с mm (по подразбиране), cm или in.</translation>
    </message>
    <message>
        <source>Approximate corners in photo pixels, x,y;x,y;x,y;x,y in any order: the edges are searched near them.</source>
        <translation>Приблизителни ъгли в пиксели на снимката, x,y;x,y;x,y;x,y в произволен ред: ръбовете се търсят близо до тях.</translation>
    </message>
    <message>
        <source>--sheet needs a4, a3, letter or WxH[mm|cm|in], got &quot;%1&quot;</source>
        <translation>--sheet изисква a4, a3, letter или WxH[mm|cm|in], получено „%1“</translation>
    </message>
    <message>
        <source>--corners needs four points x,y separated by semicolons or spaces</source>
        <translation>--corners изисква четири точки x,y, разделени с точка и запетая или интервали</translation>
    </message>
    <message>
        <source>%1: cannot read the photo</source>
        <translation>%1: снимката не може да бъде прочетена</translation>
    </message>
    <message>
        <source>Trace a pattern photographed beside a reference sheet: the sheet is found (its corners to a
fraction of a pixel), the photo rectified into the sheet&apos;s plane and every pattern piece&apos;s outline
written as a closed composite curve in mm to OUT.kontur, with the photo as its calibrated
background. --json prints the corners, the calibration&apos;s estimated error and each curve&apos;s knots.</source>
        <translation>Обрисуване на кройка, снимана до еталонен лист: листът се намира (ъглите му с точност до част
от пиксела), снимката се изправя в равнината на листа и контурът на всеки детайл от кройката се
записва в OUT.kontur като затворена съставна крива в мм, със снимката като калибрирано фоново
изображение. --json извежда ъглите, оценената грешка на калибрирането и възлите на всяка крива.</translation>
    </message>
    <message>
        <source>The document to write (.kontur).</source>
        <translation>Документът за запис (.kontur).</translation>
    </message>
    <message>
        <source>Print the sheet&apos;s corners, the calibration error and the outlines&apos; knots as JSON.</source>
        <translation>Извежда ъглите на листа, грешката на калибрирането и възлите на контурите като JSON.</translation>
    </message>
    <message>
        <source>trace needs an output file OUT.kontur, or --json for the sheet&apos;s corners</source>
        <translation>за обрисуване (trace) е нужен изходен файл OUT.kontur или --json за ъглите на листа</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1: curve %2: %3</source>
        <translation>%1: крива %2: %3</translation>
    </message>
    <message>
        <source>no such file</source>
        <translation>няма такъв файл</translation>
    </message>
    <message>
        <source>its symbolic links form a loop</source>
        <translation>символните му връзки образуват цикъл</translation>
    </message>
    <message>
        <source>permission denied</source>
        <translation>достъпът е отказан</translation>
    </message>
    <message>
        <source>it is a folder, not a file</source>
        <translation>това е папка, а не файл</translation>
    </message>
    <message>
        <source>it is a named pipe (FIFO), not a regular file</source>
        <translation>това е именуван канал (FIFO), а не обикновен файл</translation>
    </message>
    <message>
        <source>it is a device, not a regular file</source>
        <translation>това е устройство, а не обикновен файл</translation>
    </message>
    <message>
        <source>it is not a regular file</source>
        <translation>това не е обикновен файл</translation>
    </message>
    <message>
        <source>%1: a CSV file holds the points of one curve; the input has %2: choose one with --curve N</source>
        <translation>%1: CSV файлът съдържа точките на една крива; входът има %2: изберете една с --curve N</translation>
    </message>
    <message>
        <source>%1: unknown language &quot;%2&quot;; choose one of: %3.</source>
        <extracomment>%1 is the program (kontur or kontur-cli), %2 the language code asked for, %3 the codes there are.</extracomment>
        <translation>%1: непознат език „%2“; изберете един от: %3.</translation>
    </message>
    <message>
        <source>Rounds of parameter correction (default 0: the parameters are used as computed).</source>
        <translation>Брой итерации за корекция на параметрите (по подразбиране 0: параметрите се използват както са пресметнати).</translation>
    </message>
    <message>
        <source>%1: %2 points; a least-squares cubic needs at least 4</source>
        <translation>%1: брой точки %2; кубичната крива по метода на най-малките квадрати изисква поне 4</translation>
    </message>
    <message>
        <source>Work with the Bézier curve whose control points are in the file. Prints the control points (JSON key control_points) when --elevate is given or when nothing else is asked for.</source>
        <translation>Работи с кривата на Безие, чиито контролни точки са във файла. Извежда контролните точки (ключ в JSON control_points) при --elevate или когато нищо друго не е поискано.</translation>
    </message>
    <message>
        <source>%1: %2 points; a Bézier curve needs at least 2</source>
        <extracomment>%1 is a file name, %2 the number of points in it.</extracomment>
        <translation>%1: брой точки %2; кривата на Безие изисква поне 2</translation>
    </message>
    <message>
        <source>%1: %2 points; a closed composite curve needs at least 3</source>
        <extracomment>%1 is a file name, %2 the number of points in it.</extracomment>
        <translation>%1: брой точки %2; затворената съставна крива изисква поне 3</translation>
    </message>
    <message>
        <source>%1: %2 points; a composite curve needs at least 2</source>
        <translation>%1: брой точки %2; съставната крива изисква поне 2</translation>
    </message>
    <message>
        <source>clamped on evenly spaced knots (--function over evenly spaced x, or --param uniform): classical (default, k - 2 unknowns) or torok (Török&apos;s half-size system); prints the JSON key &quot;solverDifference&quot;: the largest difference of the derivatives from the other solver.</source>
        <translation>clamped при равномерно разположени възли (--function над равномерно разположени x или --param uniform): classical (по подразбиране, k - 2 неизвестни) или torok (системата на Тьорьок с половин размер); извежда ключа в JSON &quot;solverDifference&quot;: най-голямата разлика на производните спрямо другия метод.</translation>
    </message>
    <message>
        <source>Evaluate at u1,u2,… (a negative first value needs the = form: --at=-1,0.5).</source>
        <translation>Пресмята при u1, u2, … (отрицателна първа стойност се пише с =: --at=-1,0.5).</translation>
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
        <translation>Употреба: kontur-cli &lt;команда&gt; [опции]   (kontur-cli &lt;команда&gt; --help показва опциите ѝ)
Инструмент на Kontur за командния ред: криви на Безие и сплайни без прозорец.

Команди:
  fit        кубична крива през 4 точки или кубична крива по метода на най-малките квадрати през n &gt;= 4 точки
  bezier     пресмятане, увеличаване на степента, измерване и заявки за крива на Безие от произволна степен
  composite  съставната крива през възли с отчет за непрекъснатостта
  spline     крива от всеки вид през точки, построена както в приложението (bezier,
             composite, natural, clamped, hermite, bspline, function-spline, contour, …)
  convert    преобразува IN OUT между текст с точки (.txt), CSV, .kontur, SVG, DXF и PDF (по разширение;
             изходът PDF е кройката, отпечатана в действителен размер)
  info       кривите на файл като JSON: видове, дължини, обхващащ правоъгълник, непрекъснатост
  offset     добавки за шев: отместени криви IN OUT на дадено разстояние, отвън или отвътре
  trace      обрисуване на кройка, снимана до еталонен лист, в документ в мм
  bench      измерва времето на операция от геометричното ядро (за разработчици)

Входните файлове съдържат по една двойка „x y“ на ред; &apos;#&apos; започва коментар. Изходът е JSON на stdout;
грешките отиват в stderr с код 1 (грешен вход) или 2 (грешна употреба).
</translation>
    </message>
    <message>
        <source>The curve of a kind through the points of a file (one &quot;x y&quot; per line), built by the same function as the app&apos;s curve of that kind: bezier (the points are its control points), interpolating, least-squares, composite, natural, clamped, not-a-knot, periodic, catmull-rom, hermite, bspline (the points are its control polygon), global-bspline, polynomial, function-spline (the natural spline y(x)) or contour (Bézier pieces joined at the midpoints of pairs of points). Prints {&quot;knots&quot;: parameter of each point (the knot vector for bspline; 0, 1, … one per piece for bezier, interpolating, least-squares, composite and contour), &quot;segments&quot;: Bézier control points of each piece, &quot;points&quot;: [u, x, y] at --at}. Parameters are unnormalised: uniform 0, 1, 2, …; chord the cumulative chord length; centripetal the cumulative square roots.</source>
        <translation>Кривата от даден вид през точките на файл (по едно „x y“ на ред), построена със същата функция като кривата от този вид в приложението: bezier (точките са контролните ѝ точки), interpolating (интерполиращата кубична крива), least-squares, composite, natural, clamped, not-a-knot, periodic, catmull-rom, hermite, bspline (точките са контролният му полигон), global-bspline, polynomial, function-spline (естественият сплайн y(x)) или contour (парчета на Безие, съединени в средите на двойки точки). Извежда {&quot;knots&quot;: параметърът на всяка точка (за bspline възловият вектор; за bezier, interpolating, least-squares, composite и contour 0, 1, …, по един за парче), &quot;segments&quot;: контролните точки на Безие за всяко парче, &quot;points&quot;: [u, x, y] при --at}. Параметрите не са нормирани: uniform 0, 1, 2, …; chord натрупаната дължина на хордите; centripetal натрупаните квадратни корени.</translation>
    </message>
    <message>
        <source>B-spline order k, 2 to 10 (default as in the app: 4, cubic, or the number of points when fewer).</source>
        <translation>Ред на B-сплайна k, от 2 до 10 (по подразбиране както в приложението: 4, кубичен, или броят на точките, ако са по-малко).</translation>
    </message>
    <message>
        <source>B-spline knot vector: open-uniform (default, the app&apos;s knots), uniform, or u0,u1,… (n + k values).</source>
        <translation>Възлов вектор на B-сплайна: open-uniform (по подразбиране, възлите на приложението), uniform или u0,u1,… (n + k стойности).</translation>
    </message>
    <message>
        <source>hermite: a file with one tangent &quot;x y&quot; per point (default Catmull–Rom tangents, as in the app).</source>
        <translation>hermite: файл с по един направляващ вектор „x y“ за всяка точка (по подразбиране направляващите вектори на Катмъл–Ром, както в приложението).</translation>
    </message>
    <message>
        <source>composite: the closed curve (as Close curve makes it in the app).</source>
        <translation>composite: затворената крива (както я прави „Затваряне на кривата“ в приложението).</translation>
    </message>
    <message>
        <source>--closed is for --kind composite (the periodic spline is closed by its kind)</source>
        <translation>--closed е за --kind composite (периодичният сплайн е затворен по вида си)</translation>
    </message>
    <message>
        <source>%1: not drawn: %2</source>
        <translation>%1: не е изчертано: %2</translation>
    </message>
    <message>
        <source>Units of a DXF that names none: mm, cm, in or px (default px).</source>
        <translation>Мерни единици на DXF, който не ги посочва: mm, cm, in или px (по подразбиране px).</translation>
    </message>
    <message>
        <source>--units needs mm, cm, in or px</source>
        <translation>--units изисква mm, cm, in или px</translation>
    </message>
    <message>
        <source>DXF output as ASTM D6673 (AAMA) garment pieces: a block per closed curve, its cut line (its seam allowance, if any) and texts on layer 1, sew line 14, notches 4, mirror line 6, the piece&apos;s own grain line 7 (none if it has none), internal lines 8, drill holes 13; polylines unless --dxf spline is given.</source>
        <translation>Изход DXF като детайли на облекло по ASTM D6673 (AAMA): блок за всяка затворена крива, линията на рязане (добавката за шев, ако има) и текстовете на слой 1, линията на шева 14, засечките 4, линията на сгъвката (огледална) 6, собствената линия на основата на детайла 7 (никаква, ако няма), вътрешните линии 8, пробивите 13; начупени линии, освен ако е дадено --dxf spline (сплайни).</translation>
    </message>
    <message>
        <source>%1: the sheet is not flat (its edges are not straight); lay it flat and photograph it again, or give its four corners roughly with --corners x,y;x,y;x,y;x,y</source>
        <translation>%1: листът не е равен (ръбовете му не са прави); поставете го да лежи равно и го снимайте отново или задайте приблизително четирите му ъгъла с --corners x,y;x,y;x,y;x,y</translation>
    </message>
    <message>
        <source>%1: the rectangle found is about %2 : 1, not %3 (%4 : 1); give the sheet&apos;s size with --sheet, or its four corners roughly with --corners x,y;x,y;x,y;x,y</source>
        <extracomment>%2 and %4 are proportions such as 2.35 and 1.41 (long side : short side), %3 the sheet&apos;s size as given.</extracomment>
        <translation>%1: намереният правоъгълник е около %2 : 1, а не %3 (%4 : 1); задайте размера на листа с --sheet или приблизително четирите му ъгъла с --corners x,y;x,y;x,y;x,y</translation>
    </message>
    <message>
        <source>%1: no reference sheet found (a white rectangle with four straight, clear edges); give its four corners roughly with --corners x,y;x,y;x,y;x,y</source>
        <translation>%1: не е намерен еталонен лист (бял правоъгълник с четири прави, ясни ръба); задайте приблизително четирите му ъгъла с --corners x,y;x,y;x,y;x,y</translation>
    </message>
    <message>
        <source>%1: no pattern piece found beside the sheet; nothing was written (the sheet was found)</source>
        <translation>%1: до листа не е намерен детайл от кройката; нищо не е записано (листът е намерен)</translation>
    </message>
    <message>
        <source>%1: no grain line written for pieces without a grainline: %2</source>
        <translation>%1: за детайлите без посока на основата не е записана линия на основата: %2</translation>
    </message>
</context>
<context>
    <name>kontur::print</name>
    <message>
        <source>Print at 100 % (actual size, not “fit to page”). The grey square must measure 10 cm each way.</source>
        <translation>Печатайте в мащаб 100 % (действителен размер, без „побиране в страницата“). Сивият квадрат трябва да е 10 см във всяка посока.</translation>
    </message>
    <message>
        <source>landscape</source>
        <extracomment>Page orientation, inserted after the paper name in the sentence above (A4 landscape).</extracomment>
        <translation>пейзажна ориентация</translation>
    </message>
    <message>
        <source>portrait</source>
        <translation>портретна ориентация</translation>
    </message>
    <message>
        <source>Cut each page along the grey line at its left and top, lay it over its neighbours up to their dashed lines, match the circles and tape.</source>
        <translation>Изрежете всяка страница отляво и отгоре по сивата линия, поставете я върху съседните до техните пунктирни линии, съвместете кръгчетата и залепете.</translation>
    </message>
    <message>
        <source>The drawing is in px: printed at 96 px per inch.</source>
        <translation>Чертежът е в пиксели (px): отпечатан при 96 px на инч.</translation>
    </message>
    <message>
        <source>10 cm</source>
        <translation>10 см</translation>
    </message>
    <message>
        <source>4 in</source>
        <translation>4 инча</translation>
    </message>
    <message>
        <source>Pages after this one: %1 (rows × columns: %2 × %3), %4 %5, overlap %6 mm.</source>
        <extracomment>%1 is the number of pages, %2 × %3 their rows and columns, %4 the paper (A4 or Letter), %5 the orientation (“portrait” or “landscape”, the next messages), %6 a number of millimetres.</extracomment>
        <translation>Следващи страници: %1 (редове × колони: %2 × %3), %4, %5, застъпване %6 мм.</translation>
    </message>
    <message>
        <source>Place on fold</source>
        <extracomment>Printed along a pattern piece&apos;s fold line: the piece is laid with this edge on the fabric&apos;s fold.</extracomment>
        <translation>Постави на сгъвка</translation>
    </message>
    <message>
        <source>Size %1</source>
        <extracomment>A pattern piece&apos;s size on the printed pattern (a garment size such as 38 or M).</extracomment>
        <translation>Размер %1</translation>
    </message>
    <message numerus="yes">
        <source>Cut %n on fold</source>
        <extracomment>How many pieces to cut, printed on the pattern piece; the piece lies on the fabric&apos;s fold.</extracomment>
        <translation>
            <numerusform>Крои се %n бр. на сгъвка</numerusform>
            <numerusform>Крои се %n бр. на сгъвка</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Cut %n</source>
        <extracomment>How many pieces to cut, printed on the pattern piece (&quot;Cut 2&quot;).</extracomment>
        <translation>
            <numerusform>Крои се %n бр.</numerusform>
            <numerusform>Крои се %n бр.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 in</source>
        <extracomment>A seam&apos;s allowance width printed beside it on the pattern, in inches.</extracomment>
        <translation>%1 инча</translation>
    </message>
    <message>
        <source>%1 cm</source>
        <extracomment>A seam&apos;s allowance width printed beside it on the pattern, in centimetres (&quot;3 cm&quot;).</extracomment>
        <translation>%1 см</translation>
    </message>
</context>
<context>
    <name>messages</name>
    <message>
        <source>Do you want to reset everything? All curves will be removed.</source>
        <translation>Искате ли да изчистите всичко? Всички криви ще бъдат премахнати.</translation>
    </message>
    <message>
        <source>“%1” is locked: unlock it to change it.</source>
        <translation>„%1“ е заключена: отключете я, за да я промените.</translation>
    </message>
    <message>
        <source>Could not read “%1”: %2</source>
        <translation>Файлът „%1“ не може да бъде прочетен: %2</translation>
    </message>
    <message numerus="yes">
        <source>%n curve(s) read from “%1”.</source>
        <translation>
            <numerusform>От файла „%1“ е прочетена %n крива.</numerusform>
            <numerusform>От файла „%1“ са прочетени %n криви.</numerusform>
        </translation>
    </message>
    <message>
        <source>Saved “%1”.</source>
        <translation>Файлът „%1“ е запазен.</translation>
    </message>
    <message>
        <source>This knot lies on the first knot of the closed curve, which joins them already. Nothing was changed.</source>
        <translation>Този възел съвпада с първия възел на затворената крива, която вече ги свързва. Нищо не е променено.</translation>
    </message>
    <message>
        <source>This seam allowance follows its curve: change the curve or the allowance&apos;s settings, or detach the allowance to edit it.</source>
        <translation>Тази добавка за шев следва кривата си: променете кривата или настройките на добавката или я отделете, за да я редактирате.</translation>
    </message>
    <message>
        <source>No seam allowance of this width fits the curve on that side.</source>
        <translation>Добавка за шев с тази ширина не се побира в кривата от тази страна.</translation>
    </message>
    <message>
        <source>This width is more than %1 times the size of the curve: no seam allowance is made of it. Nothing was changed.</source>
        <translation>Тази ширина е повече от %1 пъти размера на кривата: такава добавка за шев не се създава. Нищо не е променено.</translation>
    </message>
    <message>
        <source>This seam allowance would need too many pieces at this size. Nothing was changed.</source>
        <translation>Тази добавка за шев би изисквала твърде много сегменти при този размер. Нищо не е променено.</translation>
    </message>
    <message>
        <source>The seam allowance “%1” keeps the shape it was saved with: its width %2 gives no allowance of its curve.</source>
        <translation>Добавката за шев „%1“ запазва формата, с която е записана: ширината ѝ %2 не дава добавка за кривата ѝ.</translation>
    </message>
    <message numerus="yes">
        <source>The autosave setting “%1” cannot be used: a recovery copy is saved every %n second(s).</source>
        <translation>
            <numerusform>Настройката за автоматично записване „%1“ не може да се използва: копие за възстановяване се записва на всяка %n секунда.</numerusform>
            <numerusform>Настройката за автоматично записване „%1“ не може да се използва: копие за възстановяване се записва на всеки %n секунди.</numerusform>
        </translation>
    </message>
    <message>
        <source>The background image “%1” is missing or cannot be read. The curves are shown without it.</source>
        <translation>Фоновото изображение „%1“ липсва или не може да бъде прочетено. Кривите се показват без него.</translation>
    </message>
    <message>
        <source>The picture “%1” could not be loaded: the file is missing or is not a picture Kontur can read.</source>
        <extracomment>%1 is a file name. The background picture could not be loaded.</extracomment>
        <translation>Изображението „%1“ не може да се зареди: файлът липсва или не е изображение, което Kontur може да прочете.</translation>
    </message>
    <message>
        <source>The .txt file is not in the expected format: one “x y” pair per line.</source>
        <translation>Файлът .txt не е в очаквания формат: по една двойка „x y“ на ред.</translation>
    </message>
    <message>
        <source>Could not append to “%1”: %2</source>
        <extracomment>%1 is a file name, %2 the reason (from the system). The curve&apos;s points are appended to a .txt file.</extracomment>
        <translation>Не може да се добави към „%1“: %2</translation>
    </message>
    <message>
        <source>The control points of curves of the kind “%1” cannot be moved: move the knots.</source>
        <extracomment>%1 is the name of a curve kind, as in the kind menu (&quot;Natural spline&quot;, &quot;Composite curve&quot;).</extracomment>
        <translation>Контролните точки на криви от вида „%1“ не могат да се местят: местете възлите.</translation>
    </message>
    <message>
        <source>The control points of a composite curve cannot be moved by keyboard: drag them.</source>
        <translation>Контролните точки на съставна крива не могат да се местят с клавиатурата: плъзнете ги.</translation>
    </message>
    <message>
        <source>Curves of the kind “%1” do not use a parameterization.</source>
        <extracomment>%1 is the name of a curve kind, as in the kind menu (&quot;Bézier curve&quot;, &quot;Natural spline&quot;).</extracomment>
        <translation>Кривите от вида „%1“ не използват параметризация.</translation>
    </message>
    <message>
        <source>Too many points: a curve of this kind can have at most %1.</source>
        <extracomment>%1 is the largest number of points a curve of this kind can have (for example 1 000).</extracomment>
        <translation>Твърде много точки: крива от този вид може да има най-много %1.</translation>
    </message>
    <message>
        <source>A curve of the kind “%1” needs at least %2 points.</source>
        <extracomment>%1 is the name of a curve kind, as in the kind menu (&quot;Bézier curve&quot;); %2 is a small number (2 to 4).</extracomment>
        <translation>Крива от вида „%1“ изисква поне %2 точки.</translation>
    </message>
    <message>
        <source>Some values are missing or are not numbers: fill in every field with a number.</source>
        <translation>Някои стойности липсват или не са числа: попълнете всяко поле с число.</translation>
    </message>
    <message>
        <source>The knots of this curve (kind “%1”) do not define a curve: they need at least 4 different positions.</source>
        <extracomment>%1 is the name of a curve kind, as in the kind menu (&quot;Least-squares cubic&quot;).</extracomment>
        <translation>Възлите на тази крива (вид „%1“) не определят крива: нужни са поне 4 различни положения.</translation>
    </message>
    <message>
        <source>Too large: the coordinates would exceed the largest number Kontur can hold (about %1). Nothing was changed.</source>
        <translation>Твърде голяма стойност: координатите биха надхвърлили най-голямото число, което Kontur може да съхранява (около %1). Нищо не е променено.</translation>
    </message>
    <message>
        <source>This is not possible for curves of the kind “%1”.</source>
        <extracomment>%1 is the name of a curve kind, as in the kind menu (&quot;Bézier curve&quot;, &quot;Global B-spline&quot;).</extracomment>
        <translation>Това не е възможно за криви от вида „%1“.</translation>
    </message>
    <message>
        <source>A seam allowance is still being computed: wait for it or cancel it first.</source>
        <translation>Добавка за шев все още се изчислява: изчакайте я или първо я откажете.</translation>
    </message>
    <message>
        <source>The seam allowance was cancelled. Nothing was changed.</source>
        <translation>Добавката за шев е отказана. Нищо не е променено.</translation>
    </message>
    <message>
        <source>The curve changed while its seam allowance was computed. Nothing was changed; add or apply it again.</source>
        <translation>Кривата се промени, докато се изчисляваше добавката ѝ за шев. Нищо не е променено; добавете я или я приложете отново.</translation>
    </message>
    <message numerus="yes">
        <source>%n text(s)</source>
        <translation>
            <numerusform>%n текст</numerusform>
            <numerusform>%n текста</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n dimension(s)</source>
        <translation>
            <numerusform>%n размер</numerusform>
            <numerusform>%n размера</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n 3D object(s)</source>
        <translation>
            <numerusform>%n 3D обект</numerusform>
            <numerusform>%n 3D обекта</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n image(s)</source>
        <translation>
            <numerusform>%n изображение</numerusform>
            <numerusform>%n изображения</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n spline(s) given only by fit points or weights</source>
        <translation>
            <numerusform>%n сплайн, зададен само с точки на напасване или тегла</numerusform>
            <numerusform>%n сплайна, зададени само с точки на напасване или тегла</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n other object(s)</source>
        <translation>
            <numerusform>%n друг обект</numerusform>
            <numerusform>%n други обекта</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n curve(s) read from “%1”; not drawn: %2.</source>
        <translation>
            <numerusform>%n крива е прочетена от „%1“; не е изчертано: %2.</numerusform>
            <numerusform>%n криви са прочетени от „%1“; не е изчертано: %2.</numerusform>
        </translation>
    </message>
    <message>
        <source>Could not write “%1”: %2 The file was left as it was.</source>
        <translation>Файлът „%1“ не може да бъде записан: %2 Файлът не е променен.</translation>
    </message>
    <message numerus="yes">
        <source>%n curve(s) read from “%1”, which does not say its units: read in %2, as chosen for such files.</source>
        <extracomment>%1 is a file name, %2 a unit (mm, cm, in or px) the user chose once for DXF files without units.</extracomment>
        <translation>
            <numerusform>%n крива е прочетена от „%1“, който не посочва мерните си единици: в %2, както е избрано за такива файлове.</numerusform>
            <numerusform>%n криви са прочетени от „%1“, който не посочва мерните си единици: в %2, както е избрано за такива файлове.</numerusform>
        </translation>
    </message>
    <message>
        <source>Not drawn: %1.</source>
        <extracomment>Appended to the message that curves were read from a file; %1 lists what was not drawn.</extracomment>
        <translation>Не е изчертано: %1.</translation>
    </message>
    <message>
        <source>DXF files that do not say their units are read in %1 from the next import on.</source>
        <extracomment>%1 is a unit (mm, cm, in or px).</extracomment>
        <translation>DXF файловете, които не посочват мерните си единици, се четат в %1 от следващото импортиране нататък.</translation>
    </message>
    <message>
        <source>Nothing was exported: pattern software takes each piece as a closed curve, and this document has no visible closed curve. Close the outline of each piece first.</source>
        <extracomment>AAMA (ASTM D6673) is the DXF that garment pattern software reads; a piece is a garment pattern piece.</extracomment>
        <translation>Нищо не е експортирано: програмите за кройки приемат всеки детайл като затворена крива, а в този документ няма видима затворена крива. Първо затворете контура на всеки детайл.</translation>
    </message>
    <message>
        <source>Seam allowance of %2 added to “%1”. To change it, select it and choose Seam allowance again.</source>
        <extracomment>%1 is the curve&apos;s name, %2 the width with its unit (10.00 mm).</extracomment>
        <translation>За кривата „%1“ е създадена добавка за шев от %2. За да я промените, маркирайте я и отново изберете „Добавка за шев“.</translation>
    </message>
    <message numerus="yes">
        <source>“%1” traced with %n knot(s). For the next piece, choose Trace outline again.</source>
        <extracomment>%1 is the new curve&apos;s name; Trace outline is the command in the Trace menu.</extracomment>
        <translation>
            <numerusform>Кривата „%1“ е обрисувана с %n възел. За следващия детайл отново изберете „Обрисуване на контура“.</numerusform>
            <numerusform>Кривата „%1“ е обрисувана с %n възела. За следващия детайл отново изберете „Обрисуване на контура“.</numerusform>
        </translation>
    </message>
    <message>
        <source>the grainline</source>
        <extracomment>One of the marks found on a traced pattern piece, listed after the curve&apos;s name.</extracomment>
        <translation>посоката на основата</translation>
    </message>
    <message>
        <source>the fold line</source>
        <extracomment>One of the marks found on a traced pattern piece: the edge laid on the fabric&apos;s fold.</extracomment>
        <translation>линията на сгъвката</translation>
    </message>
    <message numerus="yes">
        <source>%n notch(es)</source>
        <extracomment>One of the marks found on a traced pattern piece (V or slit cuts in its edge).</extracomment>
        <translation>
            <numerusform>%n засечка</numerusform>
            <numerusform>%n засечки</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n drill hole(s)</source>
        <extracomment>One of the marks found on a traced pattern piece.</extracomment>
        <translation>
            <numerusform>%n пробив</numerusform>
            <numerusform>%n пробива</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>“%1” traced with %n knot(s) as a pattern piece with %2. Check them under Pattern piece; for the next piece, choose Trace outline again.</source>
        <extracomment>%1 is the new curve&apos;s name, %2 the marks found on it (&quot;the grainline, 3 notches, 1 drill hole&quot;); Pattern piece is the command that opens the piece bar; Trace outline the command in the Trace menu.</extracomment>
        <translation>
            <numerusform>Кривата „%1“ е обрисувана с %n възел като детайл от кройката; открити знаци: %2. Проверете ги в „Детайл от кройката“; за следващия детайл отново изберете „Обрисуване на контура“.</numerusform>
            <numerusform>Кривата „%1“ е обрисувана с %n възела като детайл от кройката; открити знаци: %2. Проверете ги в „Детайл от кройката“; за следващия детайл отново изберете „Обрисуване на контура“.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>“%1” was written, but %n piece(s) without a grainline have no grain line in it: %2. Marker making cannot lay them on grain; draw each piece&apos;s grainline.</source>
        <extracomment>%1 is the file, %2 the pieces&apos; names; the grainline is the pattern piece&apos;s straight-of-grain line.</extracomment>
        <translation>
            <numerusform>„%1“ е записан, но %n детайл без посока на основата няма в него линия на основата: %2. При подреждането на кройката той не може да се положи по основата; начертайте посоката на основата на всеки детайл.</numerusform>
            <numerusform>„%1“ е записан, но %n детайла без посока на основата нямат в него линия на основата: %2. При подреждането на кройката те не могат да се положат по основата; начертайте посоката на основата на всеки детайл.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>units</name>
    <message>
        <source>%1 mm</source>
        <extracomment>A length in millimetres; %1 is a decimal number (12,35).</extracomment>
        <translation>%1 мм</translation>
    </message>
    <message>
        <source>%1 cm</source>
        <extracomment>A length in centimetres; %1 is a decimal number (1,235).</extracomment>
        <translation>%1 см</translation>
    </message>
    <message>
        <source>%1 in</source>
        <extracomment>A length in inches; %1 is a decimal number with three decimals (0,500), so the unit takes the form it has after a fraction.</extracomment>
        <translation>%1 инча</translation>
    </message>
    <message>
        <source>%1 px</source>
        <extracomment>A length in pixels of the picture; %1 is a decimal number (30,0).</extracomment>
        <translation>%1 px</translation>
    </message>
    <message>
        <source>%1 pt</source>
        <extracomment>A length in typographic points (1/72 inch); %1 is a decimal number (2,3).</extracomment>
        <translation>%1 пт</translation>
    </message>
    <message>
        <source>mm</source>
        <extracomment>The unit millimetres, alone: in a list of units and in headings such as &quot;X, mm&quot;.</extracomment>
        <translation>мм</translation>
    </message>
    <message>
        <source>cm</source>
        <extracomment>The unit centimetres, alone: in a list of units and in headings such as &quot;X, cm&quot;.</extracomment>
        <translation>см</translation>
    </message>
    <message>
        <source>in</source>
        <extracomment>The unit inches, alone: in a list of units (mm, cm, in) and in headings such as &quot;X, in&quot;.</extracomment>
        <translation>инчове</translation>
    </message>
    <message>
        <source>px</source>
        <extracomment>The unit pixels (of the picture), alone: in headings such as &quot;X, px&quot;.</extracomment>
        <translation>px</translation>
    </message>
    <message>
        <source>pt</source>
        <extracomment>The unit typographic points (1/72 inch), alone: in headings such as &quot;X, pt&quot;.</extracomment>
        <translation>пт</translation>
    </message>
</context>
</TS>
