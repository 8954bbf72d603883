<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ru">
<context>
    <name>AppActions</name>
    <message>
        <source>File</source>
        <extracomment>Menu title (noun): the file commands.</extracomment>
        <translation>Файл</translation>
    </message>
    <message>
        <source>New, open, save, import and export</source>
        <translation>Создание, открытие, сохранение, импорт и экспорт</translation>
    </message>
    <message>
        <source>Open %1</source>
        <translation>Открыть %1</translation>
    </message>
    <message>
        <source>Export PNG (view size)…</source>
        <translation>Экспортировать в PNG (по размеру окна)…</translation>
    </message>
    <message>
        <source>Export PNG (2× view size)…</source>
        <translation>Экспортировать в PNG (2× размер окна)…</translation>
    </message>
    <message>
        <source>Export PNG (4× view size)…</source>
        <translation>Экспортировать в PNG (4× размер окна)…</translation>
    </message>
    <message>
        <source>Export PNG of the whole document (2×)…</source>
        <translation>Экспортировать весь документ в PNG (2×)…</translation>
    </message>
    <message>
        <source>Quit</source>
        <translation>Выход</translation>
    </message>
    <message>
        <source>New Bézier</source>
        <extracomment>Tool-bar button, short for “New Bézier curve”: starts placing the control points of a new Bézier curve.</extracomment>
        <translation>Новая кривая Безье</translation>
    </message>
    <message>
        <source>Place 4 control points to make a cubic Bézier curve (B)</source>
        <translation>Поставьте 4 опорные точки, чтобы построить кубическую кривую Безье (B)</translation>
    </message>
    <message>
        <source>New curve</source>
        <translation>Новая кривая</translation>
    </message>
    <message>
        <source>Choose the kind of curve to place</source>
        <translation>Выберите вид кривой для построения</translation>
    </message>
    <message>
        <source>Done</source>
        <extracomment>Button: finishes the curve being placed (keeps the points placed so far).</extracomment>
        <translation>Готово</translation>
    </message>
    <message>
        <source>Finish the curve with the points placed so far (Enter)</source>
        <translation>Завершить кривую по уже поставленным точкам (Enter)</translation>
    </message>
    <message>
        <source>Move points</source>
        <translation>Перемещение точек</translation>
    </message>
    <message>
        <source>Drag points to change curves; drag the canvas to pan (Esc)</source>
        <translation>Перетаскивайте точки, чтобы изменять кривые; перетаскивайте холст, чтобы сдвигать вид (Esc)</translation>
    </message>
    <message>
        <source>Constrained handles</source>
        <translation>Схваты с ограничением</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Отменить</translation>
    </message>
    <message>
        <source>Undo (Ctrl+Z)</source>
        <translation>Отменить (Ctrl+Z)</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Повторить</translation>
    </message>
    <message>
        <source>Redo (Ctrl+Shift+Z)</source>
        <translation>Повторить (Ctrl+Shift+Z)</translation>
    </message>
    <message>
        <source>Reset all</source>
        <translation>Очистить всё</translation>
    </message>
    <message>
        <source>Remove every curve and the background picture</source>
        <translation>Удалить все кривые и фоновое изображение</translation>
    </message>
    <message>
        <source>Teaching</source>
        <extracomment>Menu title (noun): the teaching views (de Casteljau, degree elevation, basis functions…).</extracomment>
        <translation>Обучение</translation>
    </message>
    <message>
        <source>Views that show how curves are built</source>
        <translation>Виды, показывающие, как строятся кривые</translation>
    </message>
    <message>
        <source>de Casteljau construction</source>
        <translation>Построение де Кастельжо</translation>
    </message>
    <message>
        <source>Degree elevation</source>
        <translation>Повышение степени</translation>
    </message>
    <message>
        <source>Compare curve kinds</source>
        <translation>Сравнить виды кривых</translation>
    </message>
    <message>
        <source>Curvature comb and continuity</source>
        <translation>Гребёнка кривизны и непрерывность</translation>
    </message>
    <message>
        <source>Basis functions</source>
        <translation>Базисные функции</translation>
    </message>
    <message>
        <source>Function spline y(x)…</source>
        <translation>Сплайн-функция y(x)…</translation>
    </message>
    <message>
        <source>Runge phenomenon: comparison…</source>
        <translation>Явление Рунге: сравнение…</translation>
    </message>
    <message>
        <source>Cubic segments with guide vectors…</source>
        <translation>Кубические сегменты с направляющими векторами…</translation>
    </message>
    <message>
        <source>Presentation mode (F5)</source>
        <translation>Режим презентации (F5)</translation>
    </message>
    <message>
        <source>Trace</source>
        <extracomment>Menu title: the tools for tracing a pattern from a photo; a title, not an order.</extracomment>
        <translation>Обводка</translation>
    </message>
    <message>
        <source>Trace a pattern: freehand, calibrate, measure, compare</source>
        <translation>Обвести выкройку: от руки, калибровка, измерение, сравнение</translation>
    </message>
    <message>
        <source>Freehand (T)</source>
        <translation>От руки (T)</translation>
    </message>
    <message>
        <source>Calibrate background (K)</source>
        <translation>Калибровать фон (K)</translation>
    </message>
    <message>
        <source>Measure distance (M)</source>
        <translation>Измерить расстояние (M)</translation>
    </message>
    <message>
        <source>Seam length between knots (L)</source>
        <translation>Длина шва между узлами (L)</translation>
    </message>
    <message>
        <source>Move background (O)</source>
        <translation>Перемещение фона (O)</translation>
    </message>
    <message>
        <source>Snap to knots, grid and marks (S)</source>
        <translation>Привязка к узлам, сетке и меткам (S)</translation>
    </message>
    <message>
        <source>Lock background</source>
        <translation>Заблокировать фон</translation>
    </message>
    <message>
        <source>Zoom in</source>
        <translation>Увеличить</translation>
    </message>
    <message>
        <source>Zoom in (+)</source>
        <translation>Увеличить (+)</translation>
    </message>
    <message>
        <source>Zoom out</source>
        <translation>Уменьшить</translation>
    </message>
    <message>
        <source>Zoom out (−)</source>
        <translation>Уменьшить (−)</translation>
    </message>
    <message>
        <source>Fit to view</source>
        <extracomment>Command: zoom so that all curves fit in the window.</extracomment>
        <translation>Вписать в окно</translation>
    </message>
    <message>
        <source>Show all curves (F)</source>
        <translation>Показать все кривые (F)</translation>
    </message>
    <message>
        <source>Grid</source>
        <extracomment>Toggle (noun): show or hide the grid on the canvas.</extracomment>
        <translation>Сетка</translation>
    </message>
    <message>
        <source>Show or hide the grid and the axes (G)</source>
        <translation>Показать или скрыть сетку и оси (G)</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Язык</translation>
    </message>
    <message>
        <source>Side panel</source>
        <translation>Боковая панель</translation>
    </message>
    <message>
        <source>Show or hide the side panel: the curves, their points and settings</source>
        <translation>Показать или скрыть боковую панель: кривые, их точки и настройки</translation>
    </message>
    <message>
        <source>Seam allowance…</source>
        <translation>Припуск на шов…</translation>
    </message>
    <message>
        <source>Calibrate perspective (Shift+K)</source>
        <translation>Калибровать перспективу (Shift+K)</translation>
    </message>
    <message>
        <source>Make line</source>
        <translation>Выпрямить сегмент</translation>
    </message>
    <message>
        <source>Make the selected segment a straight line; its knots become corners (Shift+L)</source>
        <translation>Сделать выбранный сегмент прямым; его узлы становятся угловыми (Shift+L)</translation>
    </message>
    <message>
        <source>Delete knot</source>
        <translation>Удалить узел</translation>
    </message>
    <message>
        <source>Delete the selected knot; its two segments become one</source>
        <translation>Удалить выбранный узел; два его сегмента станут одним</translation>
    </message>
    <message>
        <source>Smooth knot</source>
        <translation>Гладкий узел</translation>
    </message>
    <message>
        <source>The handles of the selected knot stay on one line (Shift+S)</source>
        <translation>Направляющие точки выбранного узла остаются на одной прямой (Shift+S)</translation>
    </message>
    <message>
        <source>Symmetric knot</source>
        <translation>Симметричный узел</translation>
    </message>
    <message>
        <source>The handles of the selected knot mirror each other (Shift+Y)</source>
        <translation>Направляющие точки выбранного узла зеркально симметричны (Shift+Y)</translation>
    </message>
    <message>
        <source>Corner knot</source>
        <translation>Угловой узел</translation>
    </message>
    <message>
        <source>The handles of the selected knot move independently (Shift+C)</source>
        <translation>Направляющие точки выбранного узла перемещаются независимо (Shift+C)</translation>
    </message>
    <message>
        <source>Close curve</source>
        <translation>Замкнуть кривую</translation>
    </message>
    <message>
        <source>Join the curve&apos;s last knot to its first; ends that meet become one knot (Shift+O)</source>
        <translation>Соединить последний узел кривой с первым; сходящиеся концы становятся одним узлом (Shift+O)</translation>
    </message>
    <message>
        <source>Join curves</source>
        <translation>Соединить кривые</translation>
    </message>
    <message>
        <source>Join the selected curve with the curve whose end is nearest to one of its ends (Shift+J)</source>
        <translation>Соединить выбранную кривую с кривой, конец которой ближе всего к одному из её концов (Shift+J)</translation>
    </message>
    <message>
        <source>Simplify curve…</source>
        <translation>Упростить кривую…</translation>
    </message>
    <message>
        <source>Fewer knots within a tolerance you type</source>
        <translation>Меньше узлов в пределах введённого допуска</translation>
    </message>
    <message>
        <source>Trace outline</source>
        <translation>Обвести контур</translation>
    </message>
    <message>
        <source>The handles of composite curves keep their direction and change only their length (or drag with the right button or Shift)</source>
        <translation>Направляющие точки (схваты) составных кривых сохраняют направление и меняют только длину (или перетаскивайте правой кнопкой либо с Shift)</translation>
    </message>
    <message>
        <source>Deviation from a reference curve (D)</source>
        <translation>Отклонение от эталонной кривой (D)</translation>
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
        <translation>Масштаб %1</translation>
    </message>
    <message>
        <source>More</source>
        <extracomment>Tool-bar button that opens a menu with the commands that do not fit on the bar.</extracomment>
        <translation>Ещё</translation>
    </message>
    <message>
        <source>More commands</source>
        <translation>Другие команды</translation>
    </message>
</context>
<context>
    <name>BasisPlot</name>
    <message numerus="yes">
        <source>Too many basis functions to draw (%n).</source>
        <translation>
            <numerusform>Слишком много базисных функций для рисования (%n).</numerusform>
            <numerusform>Слишком много базисных функций для рисования (%n).</numerusform>
            <numerusform>Слишком много базисных функций для рисования (%n).</numerusform>
        </translation>
    </message>
    <message>
        <source>Bernstein polynomials of degree %1</source>
        <translation>Многочлены Бернштейна степени %1</translation>
    </message>
    <message>
        <source>B-spline basis functions N(i,k), order k = %1</source>
        <translation>Базисные функции B-сплайна N(i,k), порядок k = %1</translation>
    </message>
    <message>
        <source>Bell functions Bs of degree %1</source>
        <extracomment>Title: the bell-shaped B-spline basis functions Bs (one bell per knot) of degree %1 (a number).</extracomment>
        <translation>Колоколообразные функции Bs степени %1</translation>
    </message>
    <message>
        <source>Hermite basis functions on one segment</source>
        <translation>Базисные функции Эрмита на одном сегменте</translation>
    </message>
    <message>
        <source>Knot vector: %1</source>
        <translation>Узловой вектор: %1</translation>
    </message>
    <message>
        <source> (sum %1)</source>
        <translation> (сумма %1)</translation>
    </message>
    <message numerus="yes">
        <source>Hermite basis functions on the curve&apos;s %n segment(s)</source>
        <translation>
            <numerusform>Базисные функции Эрмита на %n сегменте кривой</numerusform>
            <numerusform>Базисные функции Эрмита на %n сегментах кривой</numerusform>
            <numerusform>Базисные функции Эрмита на %n сегментах кривой</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>BasisPlotPanel</name>
    <message>
        <source>Collapse the basis functions</source>
        <translation>Свернуть базисные функции</translation>
    </message>
    <message>
        <source>Expand the basis functions</source>
        <translation>Развернуть базисные функции</translation>
    </message>
    <message>
        <source>Of the selected curve</source>
        <extracomment>Choices of the basis functions plotted: the selected curve&apos;s own, or a family named with its basis.</extracomment>
        <translation>Выбранной кривой</translation>
    </message>
    <message>
        <source>B-spline</source>
        <translation>B-сплайн</translation>
    </message>
    <message>
        <source>Bell functions</source>
        <translation>Колоколообразные</translation>
    </message>
    <message>
        <source>Basis functions</source>
        <translation>Базисные функции</translation>
    </message>
    <message>
        <source>Degree</source>
        <translation>Степень</translation>
    </message>
    <message>
        <source>Order</source>
        <extracomment>Label (noun): the order k of the B-spline basis functions (degree + 1), a number.</extracomment>
        <translation>Порядок</translation>
    </message>
    <message>
        <source>Functions</source>
        <extracomment>Label (noun): how many basis functions are drawn (a number beside it).</extracomment>
        <translation>Функции</translation>
    </message>
    <message>
        <source>Number of basis functions</source>
        <translation>Число базисных функций</translation>
    </message>
    <message>
        <source>Close the basis functions</source>
        <translation>Закрыть базисные функции</translation>
    </message>
    <message>
        <source>Plot of the basis functions; the left and right arrow keys move t</source>
        <translation>График базисных функций; стрелки влево и вправо меняют t</translation>
    </message>
    <message>
        <source>Bernstein basis</source>
        <translation>Базис Бернштейна</translation>
    </message>
    <message>
        <source>Hermite basis</source>
        <translation>Базис Эрмита</translation>
    </message>
    <message>
        <source>Make the basis functions smaller</source>
        <translation>Уменьшить базисные функции</translation>
    </message>
    <message>
        <source>Enlarge the basis functions</source>
        <translation>Увеличить базисные функции</translation>
    </message>
</context>
<context>
    <name>BottomSheet</name>
    <message>
        <source>Panel size: tap to show more, drag to resize</source>
        <translation>Высота панели: коснитесь, чтобы показать больше, потяните, чтобы изменить</translation>
    </message>
</context>
<context>
    <name>CanvasView</name>
    <message>
        <source>grid %1</source>
        <extracomment>%1 is the grid spacing in the document&apos;s units (a number).</extracomment>
        <translation>сетка %1</translation>
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
        <translation>Нет</translation>
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
        <translation>Сбросить</translation>
    </message>
    <message>
        <source>Add row</source>
        <translation>Добавить строку</translation>
    </message>
    <message>
        <source>Delete row</source>
        <translation>Удалить строку</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>Копировать</translation>
    </message>
</context>
<context>
    <name>FileActions</name>
    <message>
        <source>New</source>
        <extracomment>Command (verb/adjective): start a new, empty document.</extracomment>
        <translation>Создать</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Открыть…</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Сохранить</translation>
    </message>
    <message>
        <source>Save as…</source>
        <translation>Сохранить как…</translation>
    </message>
    <message>
        <source>Export SVG…</source>
        <translation>Экспортировать в SVG…</translation>
    </message>
    <message>
        <source>Export the selected curve as CSV…</source>
        <translation>Экспортировать выбранную кривую в CSV…</translation>
    </message>
    <message>
        <source>Append the selected curve to a points file…</source>
        <translation>Дописать выбранную кривую в конец файла точек…</translation>
    </message>
    <message>
        <source>Kontur documents (*.kontur)</source>
        <translation>Документы Kontur (*.kontur)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Все файлы (*)</translation>
    </message>
    <message>
        <source>Open</source>
        <extracomment>Title of the file dialog that opens a document (verb: open a file).</extracomment>
        <translation>Открыть</translation>
    </message>
    <message>
        <source>Save as</source>
        <translation>Сохранить как</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Импорт</translation>
    </message>
    <message>
        <source>Export SVG</source>
        <translation>Экспорт в SVG</translation>
    </message>
    <message>
        <source>SVG images (*.svg)</source>
        <translation>Изображения SVG (*.svg)</translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation>Экспорт в CSV</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>Файлы CSV (*.csv)</translation>
    </message>
    <message>
        <source>Append to a points file</source>
        <translation>Дописать в конец файла точек</translation>
    </message>
    <message>
        <source>Points files (*.txt)</source>
        <translation>Файлы точек (*.txt)</translation>
    </message>
    <message>
        <source>Export PNG</source>
        <translation>Экспорт в PNG</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>Изображения PNG (*.png)</translation>
    </message>
    <message>
        <source>Load background image</source>
        <translation>Загрузить фоновое изображение</translation>
    </message>
    <message>
        <source>Images (*.png *.jpg *.jpeg *.heic *.heif *.bmp *.gif *.webp)</source>
        <translation>Изображения (*.png *.jpg *.jpeg *.heic *.heif *.bmp *.gif *.webp)</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Несохранённые изменения</translation>
    </message>
    <message>
        <source>“%1” has changes that are not saved. Save them first?</source>
        <translation>В документе «%1» есть несохранённые изменения. Сначала сохранить их?</translation>
    </message>
    <message>
        <source>Don’t save</source>
        <translation>Не сохранять</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message>
        <source>Recover unsaved work</source>
        <translation>Восстановить несохранённую работу</translation>
    </message>
    <message>
        <source>Kontur was not closed properly last time. Recover the unsaved work?</source>
        <translation>В прошлый раз Kontur был закрыт некорректно. Восстановить несохранённую работу?</translation>
    </message>
    <message>
        <source>Recover</source>
        <translation>Восстановить</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Отбросить</translation>
    </message>
    <message>
        <source>Print pattern…</source>
        <translation>Напечатать выкройку…</translation>
    </message>
    <message>
        <source>Print pattern to PDF</source>
        <translation>Печать выкройки в PDF</translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation>Файлы PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Kontur documents and printed patterns (%1)</source>
        <translation>Документы Kontur и напечатанные выкройки (%1)</translation>
    </message>
    <message>
        <source>Import points, CSV, SVG or DXF…</source>
        <translation>Импортировать точки, CSV, SVG или DXF…</translation>
    </message>
    <message>
        <source>Export DXF with splines…</source>
        <translation>Экспортировать в DXF со сплайнами…</translation>
    </message>
    <message>
        <source>The exact curves as DXF splines, in the document&apos;s units, for CAD and pattern software</source>
        <translation>Точные кривые как сплайны DXF в единицах документа — для САПР и программ работы с выкройками</translation>
    </message>
    <message>
        <source>Export DXF with polylines…</source>
        <translation>Экспортировать в DXF ломаными…</translation>
    </message>
    <message>
        <source>The curves as DXF polylines within 0.05 mm, for plotters and cutters without splines</source>
        <translation>Кривые как ломаные DXF с точностью 0,05 мм — для плоттеров и режущих машин без сплайнов</translation>
    </message>
    <message>
        <source>Points, CSV, SVG and DXF files (%1)</source>
        <translation>Файлы точек, CSV, SVG и DXF (%1)</translation>
    </message>
    <message>
        <source>Points, CSV, SVG, DXF, Kontur files and printed patterns (%1)</source>
        <translation>Файлы точек, CSV, SVG, DXF, Kontur и напечатанные выкройки (%1)</translation>
    </message>
    <message>
        <source>Export DXF</source>
        <translation>Экспорт в DXF</translation>
    </message>
    <message>
        <source>DXF drawings (*.dxf)</source>
        <translation>Чертежи DXF (*.dxf)</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Экспортировать</translation>
    </message>
    <message>
        <source>Append</source>
        <translation>Дописать</translation>
    </message>
    <message>
        <source>Export DXF for pattern software (AAMA)…</source>
        <extracomment>AAMA (ASTM D6673) is the DXF that garment pattern software and cutters exchange pieces in.</extracomment>
        <translation>Экспортировать в DXF для программ работы с выкройками (AAMA)…</translation>
    </message>
    <message>
        <source>Each closed curve as a pattern piece (ASTM D6673): its seam allowance as the cut line, the curve as the sew line, polylines within 0.05 mm</source>
        <translation>Каждая замкнутая кривая как деталь выкройки (ASTM D6673): её припуск на шов — линия реза, сама кривая — линия шва, ломаные с точностью 0,05 мм</translation>
    </message>
    <message>
        <source>Export DXF for pattern software</source>
        <translation>Экспорт в DXF для программ работы с выкройками</translation>
    </message>
</context>
<context>
    <name>FileBrowserDialog</name>
    <message>
        <source>Save</source>
        <translation>Сохранить</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Открыть</translation>
    </message>
</context>
<context>
    <name>FileBrowserPage</name>
    <message>
        <source>Up one folder</source>
        <extracomment>File dialog: go to the folder that contains this one.</extracomment>
        <translation>На уровень вверх</translation>
    </message>
    <message>
        <source>Folder or file path</source>
        <extracomment>File dialog: the field that shows the folder&apos;s path and takes a typed one.</extracomment>
        <translation>Путь к папке или файлу</translation>
    </message>
    <message>
        <source>Go</source>
        <extracomment>File dialog: go to the folder or file typed into the path field.</extracomment>
        <translation>Перейти</translation>
    </message>
    <message>
        <source>There is no folder or file “%1”.</source>
        <translation>Папки или файла «%1» нет.</translation>
    </message>
    <message>
        <source>The folder “%1” cannot be read.</source>
        <translation>Не удаётся прочитать папку «%1».</translation>
    </message>
    <message>
        <source>Type a name for the file.</source>
        <translation>Введите имя файла.</translation>
    </message>
    <message>
        <source>No folders and no matching files here.</source>
        <extracomment>File dialog: the folder shown has no subfolder and no file that the filter lets through.</extracomment>
        <translation>Здесь нет ни папок, ни подходящих файлов.</translation>
    </message>
    <message>
        <source>Files of type</source>
        <extracomment>File dialog: which kinds of files the list shows.</extracomment>
        <translation>Тип файлов</translation>
    </message>
    <message>
        <source>Name</source>
        <extracomment>File dialog: the name of the file to save.</extracomment>
        <translation>Имя</translation>
    </message>
    <message>
        <source>File name</source>
        <translation>Имя файла</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message>
        <source>Replace the file?</source>
        <translation>Заменить файл?</translation>
    </message>
    <message>
        <source>“%1” already exists. Replace it?</source>
        <translation>«%1» уже существует. Заменить его?</translation>
    </message>
    <message>
        <source>Replace</source>
        <translation>Заменить</translation>
    </message>
</context>
<context>
    <name>FirstRunHint</name>
    <message>
        <source>New curve</source>
        <translation>Новая кривая</translation>
    </message>
    <message>
        <source>Tap four points of a Bézier curve</source>
        <translation>Коснитесь четырёх точек кривой Безье</translation>
    </message>
    <message>
        <source>Open a file</source>
        <translation>Открыть файл</translation>
    </message>
    <message>
        <source>A Kontur document</source>
        <translation>Документ Kontur</translation>
    </message>
    <message>
        <source>Trace a picture</source>
        <translation>Обвести изображение</translation>
    </message>
    <message>
        <source>Load a photo or scan and draw over it</source>
        <translation>Загрузите фото или скан и рисуйте поверх него</translation>
    </message>
</context>
<context>
    <name>FunctionSplinePlot</name>
    <message>
        <source>Change the function spline</source>
        <translation>Изменить сплайн-функцию</translation>
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
        <translation>Закрыть</translation>
    </message>
    <message>
        <source>Spline</source>
        <extracomment>Heading (noun): the kind of spline to draw.</extracomment>
        <translation>Сплайн</translation>
    </message>
    <message>
        <source>Natural spline</source>
        <translation>Естественный сплайн</translation>
    </message>
    <message>
        <source>Clamped spline (C-spline)</source>
        <translation>Сплайн с заданными производными на концах (C-сплайн)</translation>
    </message>
    <message>
        <source>Hermite spline (H-spline)</source>
        <translation>Сплайн Эрмита (H-сплайн)</translation>
    </message>
    <message>
        <source>Global B-spline</source>
        <translation>Глобальный B-сплайн</translation>
    </message>
    <message>
        <source>B-spline of bell functions</source>
        <translation>B-сплайн из колоколообразных функций</translation>
    </message>
    <message>
        <source>Control values</source>
        <translation>Управляющие значения</translation>
    </message>
    <message>
        <source>Function values</source>
        <translation>Значения функции</translation>
    </message>
    <message>
        <source>Regular (uniform) knots</source>
        <translation>Регулярные (равномерные) узлы</translation>
    </message>
    <message>
        <source>Interval</source>
        <extracomment>Heading (noun): the interval [a, b] of evenly spaced knots; otherwise the knots x₀ … xₙ are typed one by one.</extracomment>
        <translation>Интервал</translation>
    </message>
    <message>
        <source>Knots</source>
        <translation>Узлы</translation>
    </message>
    <message>
        <source>Derivatives (one per knot)</source>
        <translation>Производные (по одной на узел)</translation>
    </message>
    <message>
        <source>Derivatives (first and last knot)</source>
        <translation>Производные (в первом и последнем узлах)</translation>
    </message>
    <message>
        <source>Derivatives</source>
        <extracomment>Screen-reader name of the field for the derivatives at the two ends (clamped spline).</extracomment>
        <translation>Производные</translation>
    </message>
    <message>
        <source>Draw</source>
        <extracomment>Button (verb): draws the spline from the values typed above.</extracomment>
        <translation>Построить</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Отменить</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Повторить</translation>
    </message>
    <message>
        <source>Interpolating polynomial through the same points</source>
        <translation>Интерполяционный многочлен через те же точки</translation>
    </message>
    <message>
        <source>Runge&apos;s example</source>
        <translation>Пример Рунге</translation>
    </message>
    <message>
        <source>Points of Runge&apos;s example</source>
        <translation>Точки примера Рунге</translation>
    </message>
    <message>
        <source>Drag a green knot up or down, or a grey handle to change the derivative: its slope to the knot is the derivative.</source>
        <translation>Перетащите зелёный узел вверх или вниз или серую направляющую точку, чтобы изменить производную: её наклон к узлу и есть производная.</translation>
    </message>
    <message>
        <source>Runge phenomenon: comparison</source>
        <translation>Явление Рунге: сравнение</translation>
    </message>
    <message>
        <source>Solver</source>
        <translation>Метод решения</translation>
    </message>
    <message>
        <source>Classical: k − 2 unknowns</source>
        <translation>Классический: k − 2 неизвестных</translation>
    </message>
    <message>
        <source>Török: half-size system</source>
        <translation>Тёрёк: система половинного размера</translation>
    </message>
    <message>
        <source>Add to document</source>
        <translation>Добавить в документ</translation>
    </message>
    <message>
        <source>Added to the document as “%1”.</source>
        <translation>Добавлено в документ как «%1».</translation>
    </message>
    <message>
        <source>Add this spline to the drawing as a curve (undone in one step)</source>
        <translation>Добавить этот сплайн на чертёж как кривую (отменяется за один шаг)</translation>
    </message>
    <message>
        <source>Course examples</source>
        <extracomment>Heading: buttons that load the course&apos;s worked examples.</extracomment>
        <translation>Примеры из курса</translation>
    </message>
    <message>
        <source>Török&apos;s example</source>
        <extracomment>Button: loads Török&apos;s example (values 3 2 −1 0,5, end slopes 0, his solver).</extracomment>
        <translation>Пример Тёрёка</translation>
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
        <translation>Нажмите «Новая кривая Безье» и поставьте 4 точки, чтобы построить первую кривую.</translation>
    </message>
    <message>
        <source>Drag a point to move it. Drag the canvas to pan; pinch or scroll to zoom.</source>
        <translation>Перетащите точку, чтобы переместить её. Перетаскивайте холст, чтобы сдвигать вид; масштабируйте двумя пальцами или колёсиком.</translation>
    </message>
    <message>
        <source>New curve: tap or click its points (%1 placed). Press Done to finish, Esc to cancel.</source>
        <translation>Новая кривая: касайтесь или щёлкайте, чтобы ставить её точки (поставлено: %1). «Готово» — завершить, Esc — отменить.</translation>
    </message>
    <message>
        <source>New curve: tap or click point %1 of %2. Esc cancels.</source>
        <translation>Новая кривая: коснитесь или щёлкните, чтобы поставить точку %1 из %2. Esc — отмена.</translation>
    </message>
    <message>
        <source>Grainline: tap its other end.</source>
        <translation>Долевая нить: коснитесь её второго конца.</translation>
    </message>
    <message>
        <source>Grainline: tap one end, then the other.</source>
        <translation>Долевая нить: коснитесь одного конца, затем другого.</translation>
    </message>
    <message>
        <source>On fold: tap the fold line&apos;s other end.</source>
        <translation>На сгибе: коснитесь второго конца линии сгиба.</translation>
    </message>
    <message>
        <source>On fold: tap one end of the fold line, then the other.</source>
        <translation>На сгибе: коснитесь одного конца линии сгиба, затем другого.</translation>
    </message>
    <message>
        <source>Notch: tap the seam to place one; drag a notch to slide it along the seam.</source>
        <translation>Надсечка: коснитесь шва, чтобы поставить надсечку; перетащите надсечку, чтобы сдвинуть её вдоль шва.</translation>
    </message>
    <message>
        <source>Drill hole: tap where it goes.</source>
        <translation>Пробивка: коснитесь места, где она должна быть.</translation>
    </message>
    <message>
        <source>Delete mark: tap a notch, drill hole, grainline or fold line.</source>
        <translation>Удалить метку: коснитесь надсечки, пробивки, долевой нити или линии сгиба.</translation>
    </message>
    <message>
        <source>Seam allowance: tap a seam, then set its width in the bar.</source>
        <translation>Припуск на шов: коснитесь шва, затем задайте его ширину на панели.</translation>
    </message>
</context>
<context>
    <name>MessageBanner</name>
    <message>
        <source>Close message</source>
        <translation>Закрыть сообщение</translation>
    </message>
    <message>
        <source>Change units…</source>
        <extracomment>Button in the message that a DXF without units was read in the units chosen for such files.</extracomment>
        <translation>Изменить единицы…</translation>
    </message>
</context>
<context>
    <name>NumberStepper</name>
    <message>
        <source>%1 of %2</source>
        <extracomment>Which number of a typed list the − and + buttons change: %1 its place, %2 how many there are.</extracomment>
        <translation>%1 из %2</translation>
    </message>
    <message>
        <source>Previous number</source>
        <extracomment>Screen-reader name: chooses the previous number of the list for the − and + buttons.</extracomment>
        <translation>Предыдущее число</translation>
    </message>
    <message>
        <source>Next number</source>
        <extracomment>Screen-reader name: chooses the next number of the list for the − and + buttons.</extracomment>
        <translation>Следующее число</translation>
    </message>
    <message>
        <source>Decrease the marked number</source>
        <extracomment>Screen-reader name: makes the marked number of the list smaller by the step shown.</extracomment>
        <translation>Уменьшить выделенное число</translation>
    </message>
    <message>
        <source>Increase the marked number</source>
        <extracomment>Screen-reader name: makes the marked number of the list larger by the step shown.</extracomment>
        <translation>Увеличить выделенное число</translation>
    </message>
</context>
<context>
    <name>PanelDrawer</name>
    <message>
        <source>Curves and settings</source>
        <translation>Кривые и настройки</translation>
    </message>
    <message>
        <source>Unpin</source>
        <extracomment>Button (verb): let the side panel slide over the canvas instead of staying beside it.</extracomment>
        <translation>Открепить</translation>
    </message>
    <message>
        <source>Pin</source>
        <extracomment>Button (verb): keep the side panel open beside the canvas.</extracomment>
        <translation>Закрепить</translation>
    </message>
    <message>
        <source>Unpin the panel: let it slide over the canvas</source>
        <translation>Открепить панель: она будет выдвигаться поверх холста</translation>
    </message>
    <message>
        <source>Pin the panel beside the canvas</source>
        <translation>Закрепить панель рядом с холстом</translation>
    </message>
</context>
<context>
    <name>PieceBar</name>
    <message>
        <source>Pattern piece</source>
        <extracomment>Title of the bar that edits a garment pattern piece&apos;s marks.</extracomment>
        <translation>Деталь выкройки</translation>
    </message>
    <message>
        <source>Make a pattern piece</source>
        <translation>Сделать деталью выкройки</translation>
    </message>
    <message>
        <source>Select a closed curve: the outline of a pattern piece.</source>
        <translation>Выберите замкнутую кривую — контур детали выкройки.</translation>
    </message>
    <message>
        <source>Size</source>
        <extracomment>A garment size (38, M) of the pattern piece.</extracomment>
        <translation>Размер</translation>
    </message>
    <message>
        <source>Cut</source>
        <extracomment>How many pieces to cut from the fabric (“cut 2”).</extracomment>
        <translation>Кроить</translation>
    </message>
    <message>
        <source>How many to cut</source>
        <translation>Сколько кроить</translation>
    </message>
    <message>
        <source>Material</source>
        <extracomment>The fabric the pattern piece is cut from.</extracomment>
        <translation>Материал</translation>
    </message>
    <message>
        <source>Grainline</source>
        <extracomment>Tool: draw the pattern piece&apos;s grainline with two taps.</extracomment>
        <translation>Долевая нить</translation>
    </message>
    <message>
        <source>On fold</source>
        <extracomment>Tool: the fold line, the edge laid on the fabric&apos;s fold (two taps).</extracomment>
        <translation>На сгибе</translation>
    </message>
    <message>
        <source>Notch</source>
        <extracomment>Tool: place a notch by tapping the seam.</extracomment>
        <translation>Надсечка</translation>
    </message>
    <message>
        <source>Slit notch</source>
        <translation>Прямая надсечка</translation>
    </message>
    <message>
        <source>V notch</source>
        <translation>V-образная надсечка</translation>
    </message>
    <message>
        <source>Castle notch</source>
        <translation>Прямоугольная надсечка</translation>
    </message>
    <message>
        <source>Notch kind</source>
        <translation>Вид надсечки</translation>
    </message>
    <message>
        <source>Drill hole</source>
        <extracomment>Tool: mark a drill hole by a tap.</extracomment>
        <translation>Пробивка</translation>
    </message>
    <message>
        <source>Delete mark</source>
        <extracomment>Tool: delete the notch, drill hole, grainline or fold line tapped.</extracomment>
        <translation>Удалить метку</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>Готово</translation>
    </message>
    <message>
        <source>Close the pattern piece bar</source>
        <translation>Закрыть панель детали выкройки</translation>
    </message>
    <message>
        <source>Seam allowance</source>
        <extracomment>Tool: tap a seam of the pattern piece to set its own seam allowance width.</extracomment>
        <translation>Припуск на шов</translation>
    </message>
    <message>
        <source>Seam %1</source>
        <extracomment>The seam tapped (numbered from 1 along the piece) whose seam allowance the bar shows.</extracomment>
        <translation>Шов %1</translation>
    </message>
    <message>
        <source>Seam allowance %1 %2 narrower</source>
        <translation>Припуск на шов на %1 %2 уже</translation>
    </message>
    <message>
        <source>Seam allowance of the seam</source>
        <translation>Припуск на этот шов</translation>
    </message>
    <message>
        <source>Seam allowance %1 %2 wider</source>
        <translation>Припуск на шов на %1 %2 шире</translation>
    </message>
    <message>
        <source>As the piece</source>
        <extracomment>Give the seam the piece&apos;s own seam allowance width again.</extracomment>
        <translation>Как у детали</translation>
    </message>
    <message>
        <source>Hem: turned-back corners</source>
        <extracomment>Toggle: the tapped seam is a hem, so its seam allowance&apos;s corners are turned back (mirrored about the hem line) rather than mitred.</extracomment>
        <translation>Подгибка низа: отогнутые углы</translation>
    </message>
</context>
<context>
    <name>PracticumPlot</name>
    <message>
        <source>Change the segments</source>
        <translation>Изменить сегменты</translation>
    </message>
</context>
<context>
    <name>PracticumView</name>
    <message>
        <source>Cubic segments</source>
        <translation>Кубические сегменты</translation>
    </message>
    <message>
        <source>Close</source>
        <extracomment>Button (verb): closes this teaching view and returns to the drawing.</extracomment>
        <translation>Закрыть</translation>
    </message>
    <message>
        <source>Parametric segment</source>
        <translation>Параметрический сегмент</translation>
    </message>
    <message>
        <source>Spline through several points</source>
        <translation>Сплайн через несколько точек</translation>
    </message>
    <message>
        <source>Kind of segment</source>
        <translation>Вид сегмента</translation>
    </message>
    <message>
        <source>Lines per segment</source>
        <translation>Линий на сегмент</translation>
    </message>
    <message>
        <source>By lines</source>
        <translation>Линиями</translation>
    </message>
    <message>
        <source>By points</source>
        <translation>Точками</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Отменить</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Повторить</translation>
    </message>
    <message>
        <source>Drag the green points, or the grey grips at the ends of the guide vectors to change the end directions.</source>
        <translation>Перетащите зелёные точки или серые схваты на концах направляющих векторов, чтобы изменить направления на концах.</translation>
    </message>
    <message>
        <source>Function segment y(x)</source>
        <translation>Непараметрический сегмент y(x)</translation>
    </message>
    <message>
        <source>Test example</source>
        <translation>Контрольный пример</translation>
    </message>
    <message>
        <source>Segment example</source>
        <extracomment>Button: loads the practicum&apos;s single-segment example (KG-202: two points, guide vectors rising and falling at 45°), in the segment kind chosen.</extracomment>
        <translation>Пример сегмента</translation>
    </message>
</context>
<context>
    <name>PrintDialog</name>
    <message>
        <source>Print pattern</source>
        <translation>Печать выкройки</translation>
    </message>
    <message>
        <source>Print to PDF…</source>
        <translation>Напечатать в PDF…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message>
        <source>Paper</source>
        <translation>Бумага</translation>
    </message>
    <message>
        <source>Letter</source>
        <extracomment>The US paper size Letter (8.5 × 11 in), not a letter of the alphabet or a message.</extracomment>
        <translation>Letter (США)</translation>
    </message>
    <message>
        <source>Orientation</source>
        <translation>Ориентация</translation>
    </message>
    <message>
        <source>Automatic (fewer pages)</source>
        <translation>Автоматически (меньше листов)</translation>
    </message>
    <message>
        <source>Portrait</source>
        <translation>Книжная</translation>
    </message>
    <message>
        <source>Landscape</source>
        <translation>Альбомная</translation>
    </message>
    <message>
        <source>Overlap (mm)</source>
        <translation>Перекрытие (мм)</translation>
    </message>
    <message numerus="yes">
        <source>%n page(s) to tape together: %1 × %2 (rows × columns), %3.</source>
        <translation>
            <numerusform>%n лист для склейки: %1 × %2 (ряды × столбцы), %3.</numerusform>
            <numerusform>%n листа для склейки: %1 × %2 (ряды × столбцы), %3.</numerusform>
            <numerusform>%n листов для склейки: %1 × %2 (ряды × столбцы), %3.</numerusform>
        </translation>
    </message>
    <message>
        <source>landscape</source>
        <translation>альбомная ориентация</translation>
    </message>
    <message>
        <source>portrait</source>
        <translation>книжная ориентация</translation>
    </message>
    <message>
        <source>Before them, a first page with a 10 cm test square and the overview. Print at 100 % (actual size). The visible curves are printed; the background picture is not.</source>
        <translation>Перед ними — первый лист с контрольным квадратом 10 см и общим видом. Печатайте в масштабе 100 % (реальный размер). Печатаются видимые кривые, фоновое изображение — нет.</translation>
    </message>
    <message>
        <source>The drawing is in px: it is printed at 96 px per inch. Choose real units for true size.</source>
        <translation>Чертёж в пикселях (px): он печатается с разрешением 96 px на дюйм. Для реального размера выберите настоящие единицы измерения.</translation>
    </message>
</context>
<context>
    <name>SeamAllowanceDialog</name>
    <message>
        <source>Seam allowance</source>
        <translation>Припуск на шов</translation>
    </message>
    <message>
        <source>Width (%1)</source>
        <extracomment>Label: the seam allowance&apos;s width; %1 is the unit (mm, cm…).</extracomment>
        <translation>Ширина (%1)</translation>
    </message>
    <message>
        <source>Seam allowance width</source>
        <translation>Ширина припуска на шов</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Сторона</translation>
    </message>
    <message>
        <source>Outside</source>
        <translation>Снаружи</translation>
    </message>
    <message>
        <source>Inside</source>
        <translation>Внутри</translation>
    </message>
    <message>
        <source>Left of the direction</source>
        <translation>Слева по направлению</translation>
    </message>
    <message>
        <source>Right of the direction</source>
        <translation>Справа по направлению</translation>
    </message>
    <message>
        <source>Corners</source>
        <translation>Углы</translation>
    </message>
    <message>
        <source>Mitered</source>
        <translation>Острые</translation>
    </message>
    <message>
        <source>Bevelled</source>
        <translation>Срезанные</translation>
    </message>
    <message>
        <source>Rounded</source>
        <translation>Скруглённые</translation>
    </message>
    <message>
        <source>Miter limit (%1)</source>
        <extracomment>Label: the longest pointed corner; %1 is the unit (mm, cm…).</extracomment>
        <translation>Предел острого угла (%1)</translation>
    </message>
    <message>
        <source>Miter limit</source>
        <translation>Предел острого угла</translation>
    </message>
    <message>
        <source>Apply</source>
        <extracomment>Button (verb): applies the changed settings to this seam allowance.</extracomment>
        <translation>Применить</translation>
    </message>
    <message>
        <source>Add</source>
        <extracomment>Button (verb): adds a seam allowance to the selected curve.</extracomment>
        <translation>Добавить</translation>
    </message>
    <message>
        <source>Detach</source>
        <extracomment>Button (verb): cut the link between the seam allowance and its curve, so it can be edited on its own.</extracomment>
        <translation>Отвязать</translation>
    </message>
    <message>
        <source>Detach from its curve</source>
        <translation>Отвязать от кривой</translation>
    </message>
    <message>
        <source>Close</source>
        <extracomment>Button (verb): closes this dialog.</extracomment>
        <translation>Закрыть</translation>
    </message>
    <message>
        <source>Computing the seam allowance…</source>
        <translation>Вычисляется припуск на шов…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message>
        <source>Cancel the seam allowance</source>
        <translation>Отменить вычисление припуска на шов</translation>
    </message>
</context>
<context>
    <name>SidePanel</name>
    <message>
        <source>Curves</source>
        <translation>Кривые</translation>
    </message>
    <message>
        <source>No curves yet.</source>
        <translation>Кривых пока нет.</translation>
    </message>
    <message>
        <source>%1 · cannot be drawn from these points</source>
        <translation>%1 · по этим точкам не строится</translation>
    </message>
    <message numerus="yes">
        <source>%1 · %n point(s) · length %2</source>
        <extracomment>%1 is the curve&apos;s kind, %2 its length with its unit (12.5 mm).</extracomment>
        <translation>
            <numerusform>%1 · %n точка · длина %2</numerusform>
            <numerusform>%1 · %n точки · длина %2</numerusform>
            <numerusform>%1 · %n точек · длина %2</numerusform>
        </translation>
    </message>
    <message>
        <source>Selected curve</source>
        <translation>Выбранная кривая</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Название</translation>
    </message>
    <message>
        <source>Kind</source>
        <extracomment>Label (noun): the kind of the selected curve, for example “Bézier curve” or “Natural spline”.</extracomment>
        <translation>Вид</translation>
    </message>
    <message>
        <source>degree %1</source>
        <translation>степень %1</translation>
    </message>
    <message>
        <source>Parameterization</source>
        <translation>Параметризация</translation>
    </message>
    <message>
        <source>Uniform</source>
        <translation>Равномерная</translation>
    </message>
    <message>
        <source>Chord length</source>
        <translation>По длине хорд</translation>
    </message>
    <message>
        <source>Centripetal</source>
        <translation>Центростремительная</translation>
    </message>
    <message>
        <source>Order</source>
        <extracomment>Label (noun): the order k of a B-spline (degree + 1), a number; not a sequence and not a command.</extracomment>
        <translation>Порядок</translation>
    </message>
    <message>
        <source>Node type</source>
        <translation>Тип узла</translation>
    </message>
    <message>
        <source>Smooth</source>
        <extracomment>Knot type: the handles on both sides stay on one line (G1).</extracomment>
        <translation>Гладкий</translation>
    </message>
    <message>
        <source>Symmetric</source>
        <extracomment>Knot type: the handles on both sides stay on one line and have equal lengths (C1).</extracomment>
        <translation>Симметричный</translation>
    </message>
    <message>
        <source>Corner</source>
        <extracomment>Knot type: the handles on both sides move independently (a corner).</extracomment>
        <translation>Угловой</translation>
    </message>
    <message>
        <source>Colour</source>
        <translation>Цвет</translation>
    </message>
    <message>
        <source>Visible</source>
        <translation>Видима</translation>
    </message>
    <message>
        <source>Locked</source>
        <translation>Заблокирована</translation>
    </message>
    <message>
        <source>Close curve</source>
        <translation>Замкнуть кривую</translation>
    </message>
    <message>
        <source>Move up</source>
        <translation>Переместить вверх</translation>
    </message>
    <message>
        <source>Move down</source>
        <translation>Переместить вниз</translation>
    </message>
    <message>
        <source>Delete curve</source>
        <translation>Удалить кривую</translation>
    </message>
    <message>
        <source>Coordinates</source>
        <translation>Координаты</translation>
    </message>
    <message>
        <source>Info</source>
        <extracomment>Heading (noun): figures about the selected curve (length, fit error, continuity).</extracomment>
        <translation>Информация</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Длина</translation>
    </message>
    <message>
        <source>Fit error (RMS / max)</source>
        <translation>Погрешность аппроксимации (СКО / макс.)</translation>
    </message>
    <message>
        <source>Continuity</source>
        <translation>Непрерывность</translation>
    </message>
    <message>
        <source>joint %1: %2</source>
        <translation>стык %1: %2</translation>
    </message>
    <message>
        <source>Background image</source>
        <translation>Фоновое изображение</translation>
    </message>
    <message>
        <source>Load image…</source>
        <translation>Загрузить изображение…</translation>
    </message>
    <message>
        <source>Show background</source>
        <translation>Показывать фон</translation>
    </message>
    <message>
        <source>Opacity</source>
        <translation>Непрозрачность</translation>
    </message>
    <message>
        <source>Remove background</source>
        <translation>Удалить фон</translation>
    </message>
    <message>
        <source>%1 / %2</source>
        <extracomment>The fit error as RMS / maximum: %1 and %2 are numbers.</extracomment>
        <translation>%1 / %2</translation>
    </message>
    <message>
        <source>No curve selected. Tap a curve to edit it.</source>
        <translation>Кривая не выбрана. Коснитесь кривой, чтобы изменить её.</translation>
    </message>
    <message>
        <source>Curve visible</source>
        <translation>Кривая видима</translation>
    </message>
    <message>
        <source>Curve locked</source>
        <translation>Кривая заблокирована</translation>
    </message>
    <message>
        <source>Curve name</source>
        <translation>Название кривой</translation>
    </message>
    <message>
        <source>Black</source>
        <translation>Чёрный</translation>
    </message>
    <message>
        <source>Red</source>
        <translation>Красный</translation>
    </message>
    <message>
        <source>Blue</source>
        <translation>Синий</translation>
    </message>
    <message>
        <source>Green</source>
        <translation>Зелёный</translation>
    </message>
    <message>
        <source>Orange</source>
        <translation>Оранжевый</translation>
    </message>
    <message>
        <source>Purple</source>
        <translation>Фиолетовый</translation>
    </message>
    <message>
        <source>Teal</source>
        <translation>Сине-зелёный</translation>
    </message>
    <message>
        <source>Brown</source>
        <translation>Коричневый</translation>
    </message>
    <message>
        <source>Colour: %1</source>
        <translation>Цвет: %1</translation>
    </message>
    <message>
        <source>Load background image</source>
        <translation>Загрузить фоновое изображение</translation>
    </message>
    <message>
        <source>Background opacity</source>
        <translation>Непрозрачность фона</translation>
    </message>
    <message>
        <source>Pattern piece…</source>
        <extracomment>Opens the bar that makes the closed curve a garment pattern piece and edits its marks.</extracomment>
        <translation>Деталь выкройки…</translation>
    </message>
    <message>
        <source>Pattern piece</source>
        <translation>Деталь выкройки</translation>
    </message>
</context>
<context>
    <name>SimplifyDialog</name>
    <message>
        <source>Simplify curve</source>
        <translation>Упростить кривую</translation>
    </message>
    <message>
        <source>The new curve stays within this distance of the old one.</source>
        <translation>Новая кривая отклоняется от прежней не больше чем на это расстояние.</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Допуск</translation>
    </message>
    <message>
        <source>Simplify</source>
        <translation>Упростить</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
</context>
<context>
    <name>TeachingBar</name>
    <message>
        <source>de Casteljau</source>
        <translation>де Кастельжо</translation>
    </message>
    <message>
        <source>Degree elevation</source>
        <translation>Повышение степени</translation>
    </message>
    <message>
        <source>Compare</source>
        <extracomment>Name of a teaching view (verb used as a title): compare curve kinds or parameterizations side by side.</extracomment>
        <translation>Сравнить</translation>
    </message>
    <message>
        <source>Curvature comb</source>
        <translation>Гребёнка кривизны</translation>
    </message>
    <message>
        <source>Select a Bézier curve.</source>
        <translation>Выберите кривую Безье.</translation>
    </message>
    <message>
        <source>Select a curve.</source>
        <translation>Выберите кривую.</translation>
    </message>
    <message>
        <source>t = %1</source>
        <extracomment>The curve parameter t and its value (a number); keep “t”.</extracomment>
        <translation>t = %1</translation>
    </message>
    <message>
        <source>Parameter t</source>
        <translation>Параметр t</translation>
    </message>
    <message numerus="yes">
        <source>degree %1 → %2 (%n point(s))</source>
        <translation>
            <numerusform>степень %1 → %2 (%n точка)</numerusform>
            <numerusform>степень %1 → %2 (%n точки)</numerusform>
            <numerusform>степень %1 → %2 (%n точек)</numerusform>
        </translation>
    </message>
    <message>
        <source>Elevation steps</source>
        <translation>Шаги повышения степени</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Пауза</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Пуск</translation>
    </message>
    <message>
        <source>Play or pause the animation (P)</source>
        <translation>Запустить или приостановить анимацию (P)</translation>
    </message>
    <message>
        <source>Direction</source>
        <extracomment>Screen-reader name of the button that reverses the direction of the animation (forwards or backwards in t).</extracomment>
        <translation>Направление</translation>
    </message>
    <message>
        <source>Forward; press to go backward</source>
        <translation>Вперёд; нажмите, чтобы идти назад</translation>
    </message>
    <message>
        <source>Backward; press to go forward</source>
        <translation>Назад; нажмите, чтобы идти вперёд</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Скорость</translation>
    </message>
    <message>
        <source>%1×</source>
        <extracomment>Animation speed factor: %1 is a number (0,5 → “0,5×”).</extracomment>
        <translation>%1×</translation>
    </message>
    <message>
        <source>Split at t</source>
        <translation>Разделить при t</translation>
    </message>
    <message>
        <source>Reduce degree</source>
        <translation>Понизить степень</translation>
    </message>
    <message>
        <source>Replace the curve by the closest curve of one degree less</source>
        <translation>Заменить кривую ближайшей кривой на одну степень ниже</translation>
    </message>
    <message>
        <source>reduction error %1</source>
        <extracomment>Degree reduction: %1 is the largest distance between the curve and its reduced curve (a number).</extracomment>
        <translation>погрешность понижения степени %1</translation>
    </message>
    <message>
        <source>Alt+click or long press: add or remove a control point</source>
        <translation>Alt+щелчок или долгое нажатие: добавить или удалить опорную точку</translation>
    </message>
    <message>
        <source>Curve kinds</source>
        <extracomment>What the Compare view sets side by side: one curve drawn as each kind, or with each parameterization.</extracomment>
        <translation>Виды кривых</translation>
    </message>
    <message>
        <source>Parameterizations</source>
        <translation>Параметризации</translation>
    </message>
    <message>
        <source>Scale %1</source>
        <extracomment>%1 is the scale factor of the curvature comb (a number such as 2,5).</extracomment>
        <translation>Масштаб %1</translation>
    </message>
    <message>
        <source>Comb scale</source>
        <translation>Масштаб гребёнки</translation>
    </message>
    <message>
        <source>All curves</source>
        <translation>Все кривые</translation>
    </message>
    <message>
        <source>Close</source>
        <extracomment>Button (verb): closes the teaching view and returns to the drawing.</extracomment>
        <translation>Закрыть</translation>
    </message>
    <message>
        <source>Leave the teaching view</source>
        <translation>Выйти из учебного режима</translation>
    </message>
    <message>
        <source>Split the curve at t into two curves (a spline becomes a composite curve first)</source>
        <translation>Разделить кривую в точке t на две кривые (сплайн сначала становится составной кривой)</translation>
    </message>
    <message>
        <source>One elevation step less</source>
        <translation>На один шаг повышения степени меньше</translation>
    </message>
    <message>
        <source>One elevation step more</source>
        <translation>На один шаг повышения степени больше</translation>
    </message>
    <message>
        <source>One step back in t</source>
        <translation>На один шаг назад по t</translation>
    </message>
    <message>
        <source>One step forward in t</source>
        <translation>На один шаг вперёд по t</translation>
    </message>
</context>
<context>
    <name>TeachingOverlay</name>
    <message>
        <source>%1 (not possible for these points)</source>
        <translation>%1 (невозможно для этих точек)</translation>
    </message>
</context>
<context>
    <name>TraceBar</name>
    <message>
        <source>Freehand</source>
        <translation>От руки</translation>
    </message>
    <message>
        <source>Calibrate</source>
        <translation>Калибровать</translation>
    </message>
    <message>
        <source>Measure</source>
        <translation>Измерить</translation>
    </message>
    <message>
        <source>Seam length</source>
        <translation>Длина шва</translation>
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
            <numerusform>последний штрих: %n сегмент</numerusform>
            <numerusform>последний штрих: %n сегмента</numerusform>
            <numerusform>последний штрих: %n сегментов</numerusform>
        </translation>
    </message>
    <message>
        <source>Real distance</source>
        <translation>Реальное расстояние</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>Единицы измерения</translation>
    </message>
    <message>
        <source>Keep the angle</source>
        <translation>Сохранить угол</translation>
    </message>
    <message>
        <source>Make it horizontal</source>
        <translation>Горизонтально</translation>
    </message>
    <message>
        <source>Make it vertical</source>
        <translation>Вертикально</translation>
    </message>
    <message>
        <source>Alignment</source>
        <translation>Выравнивание</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Применить</translation>
    </message>
    <message>
        <source>Distance %1</source>
        <extracomment>%1 is a length with its unit, for example “12,35 mm”.</extracomment>
        <translation>Расстояние %1</translation>
    </message>
    <message>
        <source>Seam %1</source>
        <extracomment>%1 is the seam length with its unit, for example “412,50 mm”.</extracomment>
        <translation>Шов %1</translation>
    </message>
    <message>
        <source>Maximum %1 · mean %2</source>
        <extracomment>Deviation of a traced curve from the reference curve: %1 and %2 are lengths with their unit.</extracomment>
        <translation>Максимум %1 · среднее %2</translation>
    </message>
    <message>
        <source>Snap</source>
        <extracomment>Check box (verb): snap freehand strokes to the edges seen in the picture.</extracomment>
        <translation>Привязка</translation>
    </message>
    <message>
        <source>Leave the tracing tool</source>
        <translation>Выйти из инструмента обводки</translation>
    </message>
    <message>
        <source>Move background</source>
        <translation>Перемещение фона</translation>
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
        <translatorcomment>″ (inch mark) instead of дюймов: the entry must fit its box; the print dialog writes the size in full.</translatorcomment>
        <translation>Лист Letter (8,5 × 11″)</translation>
    </message>
    <message>
        <source>Mat square 1 cm</source>
        <translation>Клетка коврика 1 см</translation>
    </message>
    <message>
        <source>Mat square 10 cm</source>
        <translation>Клетка коврика 10 см</translation>
    </message>
    <message>
        <source>Mat square 1 in</source>
        <translation>Клетка коврика 1 дюйм</translation>
    </message>
    <message>
        <source>Mat square 6 in</source>
        <translation>Клетка коврика 6 дюймов</translation>
    </message>
    <message>
        <source>Other size</source>
        <translation>Другой размер</translation>
    </message>
    <message>
        <source>Known rectangle</source>
        <translation>Известный прямоугольник</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Ширина</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Высота</translation>
    </message>
    <message>
        <source>As marked: landscape</source>
        <translation>Как отмечено: альбомная</translation>
    </message>
    <message>
        <source>As marked: portrait</source>
        <translation>Как отмечено: книжная</translation>
    </message>
    <message>
        <source>As marked</source>
        <translation>Как отмечено</translation>
    </message>
    <message>
        <source>Portrait</source>
        <translation>Книжная</translation>
    </message>
    <message>
        <source>Landscape</source>
        <translation>Альбомная</translation>
    </message>
    <message>
        <source>Orientation</source>
        <translation>Ориентация</translation>
    </message>
    <message>
        <source>Clear perspective</source>
        <translation>Сбросить перспективу</translation>
    </message>
    <message>
        <source>Trace outline</source>
        <translation>Обвести контур</translation>
    </message>
    <message>
        <source>Snap to edges</source>
        <translation>Привязка к краям</translation>
    </message>
    <message>
        <source>Snap the stroke to the picture&apos;s edges</source>
        <translation>Привязать штрих к краям изображения</translation>
    </message>
    <message>
        <source>Find the sheet</source>
        <translation>Найти лист</translation>
    </message>
    <message>
        <source>Find the sheet in the background image</source>
        <translation>Найти лист на фоновом изображении</translation>
    </message>
    <message>
        <source>Estimated error at the far side: %1 mm</source>
        <translation>Оценка погрешности на дальней стороне: %1 мм</translation>
    </message>
    <message>
        <source>Knots in the last outline: %1</source>
        <translation>Узлов в последнем контуре: %1</translation>
    </message>
    <message>
        <source>in effect at this zoom: %1</source>
        <extracomment>%1 is the freehand tolerance that applies at the current zoom, with its unit (0,50 mm).</extracomment>
        <translation>действует при этом масштабе: %1</translation>
    </message>
</context>
<context>
    <name>TraceOverlay</name>
    <message>
        <source>seam %1</source>
        <extracomment>Label on the canvas: %1 is the seam length with its unit, for example “412,50 mm”.</extracomment>
        <translation>шов %1</translation>
    </message>
    <message>
        <source>max %1</source>
        <extracomment>Label on the canvas: the largest deviation from the reference curve, %1 a length with its unit.</extracomment>
        <translation>макс. %1</translation>
    </message>
    <message>
        <source>%1 px on the picture</source>
        <extracomment>%1 is a distance in pixels of the background picture (a number).</extracomment>
        <translation>%1 px на изображении</translation>
    </message>
</context>
<context>
    <name>UnitsDialog</name>
    <message>
        <source>Units of the drawing</source>
        <translation>Единицы чертежа</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Отмена</translation>
    </message>
    <message>
        <source>“%1” does not say which units its numbers are in. Read them as (asked once for such files):</source>
        <translation>В «%1» не указано, в каких единицах его числа. Читать их как (спрашивается один раз для таких файлов):</translation>
    </message>
    <message>
        <source>Read DXF files that do not say which units their numbers are in as:</source>
        <translation>Файлы DXF, в которых не указано, в каких единицах их числа, читать как:</translation>
    </message>
</context>
<context>
    <name>cli</name>
    <message>
        <source>Kontur: construct, modify and compare Bézier curves and splines.</source>
        <translation>Kontur: построение, изменение и сравнение кривых Безье и сплайнов.</translation>
    </message>
    <message>
        <source>Language of the user interface: %1.</source>
        <translation>Язык интерфейса: %1.</translation>
    </message>
    <message>
        <source>A Kontur document to open.</source>
        <translation>Открываемый документ Kontur.</translation>
    </message>
    <message>
        <source>kontur: give at most one file to open.</source>
        <translation>kontur: укажите не более одного файла для открытия.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: no such file.</source>
        <translation>kontur: не удаётся открыть «%1»: файл не найден.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: its symbolic links form a loop.</source>
        <translation>kontur: не удаётся открыть «%1»: его символические ссылки образуют цикл.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: permission denied.</source>
        <translation>kontur: не удаётся открыть «%1»: доступ запрещён.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: it is a folder, not a file.</source>
        <translation>kontur: не удаётся открыть «%1»: это папка, а не файл.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: it is not a regular file (a named pipe or a device).</source>
        <translation>kontur: не удаётся открыть «%1»: это не обычный файл (а именованный канал или устройство).</translation>
    </message>
</context>
<context>
    <name>errors</name>
    <message>
        <source>the file does not exist or cannot be read.</source>
        <translation>файл не существует или не может быть прочитан.</translation>
    </message>
    <message>
        <source>the file cannot be written there (a folder that is missing or read-only, or a full disk).</source>
        <translation>файл нельзя туда записать (папка отсутствует или доступна только для чтения, либо диск заполнен).</translation>
    </message>
    <message>
        <source>the file is larger than Kontur reads (%1 MB).</source>
        <extracomment>%1 is a size in megabytes, e.g. &quot;1 000&quot;.</extracomment>
        <translation>файл больше, чем может прочитать Kontur (%1 МБ).</translation>
    </message>
    <message>
        <source>the file holds more points than Kontur reads (%1).</source>
        <extracomment>%1 is a large number of points, e.g. &quot;6 000 000&quot;.</extracomment>
        <translation>в файле больше точек, чем может прочитать Kontur (%1).</translation>
    </message>
    <message>
        <source>the file holds more curves than Kontur reads (%1).</source>
        <translation>в файле больше кривых, чем может прочитать Kontur (%1).</translation>
    </message>
    <message>
        <source>the file&apos;s structure is nested deeper than %1 levels.</source>
        <extracomment>The file&apos;s elements (JSON or XML) are nested inside each other deeper than %1 levels.</extracomment>
        <translation>глубина вложенности структуры файла больше %1.</translation>
    </message>
    <message>
        <source>the file is not text in UTF-8.</source>
        <extracomment>UTF-8 is the name of a text encoding; keep it as it is.</extracomment>
        <translation>файл не является текстом в кодировке UTF-8.</translation>
    </message>
    <message>
        <source>a number was expected here.</source>
        <translation>здесь ожидалось число.</translation>
    </message>
    <message>
        <source>this number is too large for Kontur, or is not a number.</source>
        <translation>это число слишком велико для Kontur или не является числом.</translation>
    </message>
    <message>
        <source>more than a point on this line; in files, numbers are written with a decimal point.</source>
        <extracomment>Shown for &quot;1,5 2,5&quot; in a file: files write numbers with a decimal point.</extracomment>
        <translation>в строке больше одной точки; в файлах числа пишутся с десятичной точкой.</translation>
    </message>
    <message>
        <source>a word Kontur does not know at the start of this line.</source>
        <translation>в начале строки стоит слово, которое Kontur не знает.</translation>
    </message>
    <message>
        <source>this line names a setting but gives no value.</source>
        <translation>в строке указана настройка, но нет её значения.</translation>
    </message>
    <message>
        <source>a text in quotation marks is not closed.</source>
        <translation>текст в кавычках не закрыт.</translation>
    </message>
    <message>
        <source>a curve without points.</source>
        <translation>кривая без точек.</translation>
    </message>
    <message>
        <source>the file holds no points.</source>
        <translation>в файле нет точек.</translation>
    </message>
    <message>
        <source>the first row must be the header “x,y”.</source>
        <extracomment>&quot;x,y&quot; is the first line of the file as it must be written; keep it as it is.</extracomment>
        <translation>первая строка должна быть заголовком «x,y».</translation>
    </message>
    <message>
        <source>each row must hold exactly two values, x and y.</source>
        <translation>в каждой строке должно быть ровно два значения, x и y.</translation>
    </message>
    <message>
        <source>a kind of curve this version of Kontur does not know.</source>
        <translation>вид кривой, неизвестный этой версии Kontur.</translation>
    </message>
    <message>
        <source>a parameterization this version of Kontur does not know.</source>
        <translation>параметризация, неизвестная этой версии Kontur.</translation>
    </message>
    <message>
        <source>a kind of knot this version of Kontur does not know.</source>
        <translation>тип узла, неизвестный этой версии Kontur.</translation>
    </message>
    <message>
        <source>the points must be knots or control points.</source>
        <translation>точки должны быть узлами или опорными точками.</translation>
    </message>
    <message>
        <source>too few or too many points for this kind of curve.</source>
        <translation>слишком мало или слишком много точек для кривой этого вида.</translation>
    </message>
    <message>
        <source>these points do not suit this kind of curve (knots where control points belong, or the reverse).</source>
        <translation>эти точки не подходят для кривой этого вида (узлы вместо опорных точек или наоборот).</translation>
    </message>
    <message>
        <source>a value outside its range.</source>
        <translation>значение вне допустимого диапазона.</translation>
    </message>
    <message>
        <source>the document is damaged: it is not well-formed JSON.</source>
        <translation>документ повреждён: это некорректный JSON.</translation>
    </message>
    <message>
        <source>this is not a Kontur document.</source>
        <translation>это не документ Kontur.</translation>
    </message>
    <message>
        <source>the document was written by a newer version of Kontur.</source>
        <translation>документ записан более новой версией Kontur.</translation>
    </message>
    <message>
        <source>a value the document needs is missing.</source>
        <translation>отсутствует значение, необходимое документу.</translation>
    </message>
    <message>
        <source>a value of the wrong type (a number, a text or a list where another belongs).</source>
        <translation>значение неверного типа (число, текст или список там, где нужен другой тип).</translation>
    </message>
    <message>
        <source>the file is damaged: it is not well-formed XML.</source>
        <translation>файл повреждён: это некорректный XML.</translation>
    </message>
    <message>
        <source>this is not an SVG drawing.</source>
        <translation>это не рисунок SVG.</translation>
    </message>
    <message>
        <source>the outline of a shape (its path data) is malformed.</source>
        <translation>контур фигуры (данные её пути) задан неверно.</translation>
    </message>
    <message>
        <source>a transformation of a shape is malformed.</source>
        <translation>преобразование фигуры задано неверно.</translation>
    </message>
    <message>
        <source>the drawing holds no shapes Kontur can draw.</source>
        <translation>в рисунке нет фигур, которые Kontur может нарисовать.</translation>
    </message>
    <message>
        <source>this PDF was not printed by Kontur, so it holds no drawing Kontur can open. Open the .kontur document it came from.</source>
        <translation>этот PDF напечатан не в Kontur, поэтому в нём нет чертежа, который Kontur может открыть. Откройте документ .kontur, из которого он создан.</translation>
    </message>
    <message>
        <source>the DXF file is damaged or cut short.</source>
        <translation>файл DXF повреждён или обрезан.</translation>
    </message>
    <message>
        <source>the DXF file holds something Kontur cannot read (a binary DXF, or a shape off the drawing plane).</source>
        <translation>в файле DXF есть то, что Kontur не может прочитать (двоичный DXF или фигура вне плоскости чертежа).</translation>
    </message>
    <message>
        <source>this kind of curve cannot be written in this format.</source>
        <translation>кривую этого вида нельзя записать в этом формате.</translation>
    </message>
    <message>
        <source>too few points for this kind of curve.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>слишком мало точек для кривой этого вида.</translation>
    </message>
    <message>
        <source>its knots need at least 4 different positions.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>её узлам нужны как минимум 4 различных положения.</translation>
    </message>
    <message>
        <source>its knots lie too close together to define a curve.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>её узлы лежат слишком близко друг к другу, чтобы задать кривую.</translation>
    </message>
    <message>
        <source>a coordinate is too large for Kontur, or is not a number.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>координата слишком велика для Kontur или не является числом.</translation>
    </message>
    <message>
        <source>its values do not define a curve of its kind.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>её значения не задают кривую её вида.</translation>
    </message>
    <message>
        <source>a value out of all proportion to the curve&apos;s size.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>значение несоразмерно размеру кривой.</translation>
    </message>
    <message>
        <source>it would take more work than Kontur allows for one curve.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>это потребовало бы больше работы, чем Kontur допускает для одной кривой.</translation>
    </message>
    <message>
        <source>the work was cancelled.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>работа была отменена.</translation>
    </message>
    <message>
        <source>line %1, column %2: %3</source>
        <extracomment>Where in a file: %1 the line, %2 the column (character) in it, %3 what is wrong there.</extracomment>
        <translation>строка %1, столбец %2: %3</translation>
    </message>
    <message>
        <source>line %1: %2</source>
        <extracomment>Where in a file: %1 the line, %2 what is wrong there.</extracomment>
        <translation>строка %1: %2</translation>
    </message>
    <message>
        <source>at %1: %2</source>
        <extracomment>Where in a document: %1 is the place as the file writes it (e.g. curves[3].points[7]), %2 what is wrong.</extracomment>
        <translation>в элементе %1: %2</translation>
    </message>
    <message>
        <source>curve %1: %2</source>
        <extracomment>%1 is the curve&apos;s number in the file (1, 2, …), %2 what is wrong with it.</extracomment>
        <translation>кривая %1: %2</translation>
    </message>
    <message>
        <source>the points do not define a curve (two knots at the same place, or too few different knots).</source>
        <translation>точки не задают кривую (два узла в одном месте или слишком мало различных узлов).</translation>
    </message>
    <message>
        <source>all its points are at the same place.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>все её точки находятся в одном месте.</translation>
    </message>
    <message>
        <source>two consecutive knots are at the same place.</source>
        <extracomment>Why a curve in a file was refused, shown after “curve 3: ”.</extracomment>
        <translation>два соседних узла находятся в одном месте.</translation>
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
        <translation>Добавить %1</translation>
    </message>
    <message>
        <source>Move point</source>
        <translation>Переместить точку</translation>
    </message>
    <message>
        <source>Bézier curve</source>
        <translation>Кривая Безье</translation>
    </message>
    <message>
        <source>Bézier %1</source>
        <extracomment>Automatic name of a new curve: %1 is a running number (Bézier 3).</extracomment>
        <translation>Безье %1</translation>
    </message>
    <message>
        <source>Delete %1</source>
        <extracomment>Undo text: %1 is the name of the deleted curve.</extracomment>
        <translation>Удалить %1</translation>
    </message>
    <message>
        <source>Reorder curves</source>
        <translation>Изменить порядок кривых</translation>
    </message>
    <message>
        <source>Change background</source>
        <translation>Изменить фоновое изображение</translation>
    </message>
    <message>
        <source>Cubic through 4 points</source>
        <translation>Кубическая кривая через 4 точки</translation>
    </message>
    <message>
        <source>Least-squares cubic</source>
        <translation>Кубическая кривая по методу наименьших квадратов</translation>
    </message>
    <message>
        <source>Composite curve</source>
        <translation>Составная кривая</translation>
    </message>
    <message>
        <source>Through 4 points %1</source>
        <extracomment>Automatic name of a new cubic through 4 points: %1 is a running number.</extracomment>
        <translation>Через 4 точки %1</translation>
    </message>
    <message>
        <source>Least squares %1</source>
        <extracomment>Automatic name of a new least-squares cubic: %1 is a running number.</extracomment>
        <translation>МНК %1</translation>
    </message>
    <message>
        <source>Composite %1</source>
        <extracomment>Automatic name of a new composite curve: %1 is a running number.</extracomment>
        <translation>Составная %1</translation>
    </message>
    <message>
        <source>Change parameterization</source>
        <translation>Изменить параметризацию</translation>
    </message>
    <message>
        <source>Rename curve</source>
        <translation>Переименовать кривую</translation>
    </message>
    <message>
        <source>Change colour</source>
        <translation>Изменить цвет</translation>
    </message>
    <message>
        <source>Show curve</source>
        <translation>Показать кривую</translation>
    </message>
    <message>
        <source>Hide curve</source>
        <translation>Скрыть кривую</translation>
    </message>
    <message>
        <source>Lock curve</source>
        <translation>Заблокировать кривую</translation>
    </message>
    <message>
        <source>Unlock curve</source>
        <translation>Разблокировать кривую</translation>
    </message>
    <message>
        <source>Change node type</source>
        <translation>Изменить тип узла</translation>
    </message>
    <message>
        <source>Add point</source>
        <translation>Добавить точку</translation>
    </message>
    <message>
        <source>Delete point</source>
        <translation>Удалить точку</translation>
    </message>
    <message>
        <source>Insert knot</source>
        <translation>Вставить узел</translation>
    </message>
    <message>
        <source>Close curve</source>
        <translation>Замкнуть кривую</translation>
    </message>
    <message>
        <source>Edit coordinates</source>
        <translation>Изменить координаты</translation>
    </message>
    <message>
        <source>Reset all</source>
        <translation>Очистить всё</translation>
    </message>
    <message>
        <source>Natural spline</source>
        <translation>Естественный сплайн</translation>
    </message>
    <message>
        <source>Clamped spline</source>
        <extracomment>Curve kind: the cubic spline with given first derivatives at both ends (a complete or clamped spline).</extracomment>
        <translation>Сплайн с заданными производными на концах</translation>
    </message>
    <message>
        <source>Not-a-knot spline</source>
        <extracomment>Curve kind: the cubic spline whose second and next-to-last knots are not knots (the third derivative is continuous there).</extracomment>
        <translation>Сплайн с условием «не узел» (not-a-knot)</translation>
    </message>
    <message>
        <source>Periodic spline</source>
        <translation>Периодический сплайн</translation>
    </message>
    <message>
        <source>Catmull–Rom spline</source>
        <translation>Сплайн Катмулла — Рома</translation>
    </message>
    <message>
        <source>Hermite spline</source>
        <translation>Сплайн Эрмита</translation>
    </message>
    <message>
        <source>B-spline</source>
        <translation>B-сплайн</translation>
    </message>
    <message>
        <source>Global B-spline</source>
        <translation>Глобальный B-сплайн</translation>
    </message>
    <message>
        <source>Interpolating polynomial</source>
        <translation>Интерполяционный многочлен</translation>
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
        <translation>Изменить порядок сплайна</translation>
    </message>
    <message>
        <source>Untitled</source>
        <extracomment>The name of a document that has not been saved yet (also the suggested file name).</extracomment>
        <translation>Без имени</translation>
    </message>
    <message>
        <source>Import %1</source>
        <extracomment>Undo text: %1 is the name of the imported file.</extracomment>
        <translation>Импортировать %1</translation>
    </message>
    <message>
        <source>Split curve</source>
        <translation>Разделить кривую</translation>
    </message>
    <message>
        <source>uniform</source>
        <extracomment>Parameterization name in lower case, shown after a kind name (“Natural spline, uniform”).</extracomment>
        <translation>равномерная</translation>
    </message>
    <message>
        <source>chord length</source>
        <extracomment>Parameterization name in lower case, shown after a kind name (“Natural spline, chord length”).</extracomment>
        <translation>по длине хорд</translation>
    </message>
    <message>
        <source>centripetal</source>
        <extracomment>Parameterization name in lower case, shown after a kind name (“Natural spline, centripetal”).</extracomment>
        <translation>центростремительная</translation>
    </message>
    <message>
        <source>Reduce degree</source>
        <translation>Понизить степень</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <extracomment>Legend in the Compare view: %1 is a curve kind, %2 a parameterization (“Natural spline, uniform”).</extracomment>
        <translation>%1, %2</translation>
    </message>
    <message>
        <source>Contour curve (midpoint joins)</source>
        <extracomment>Curve kind: quadratic Bézier pieces through the midpoints of the polygon&apos;s sides, joined smoothly there.</extracomment>
        <translation>Контурная кривая (стыки в серединах)</translation>
    </message>
    <message>
        <source>Nothing to print: no curve is visible.</source>
        <translation>Нечего печатать: нет видимых кривых.</translation>
    </message>
    <message>
        <source>The drawing would need more than %1 pages at true size. Check the document&apos;s units.</source>
        <translation>В реальном размере чертёж занял бы больше %1 листов. Проверьте единицы измерения документа.</translation>
    </message>
    <message>
        <source>The drawing cannot be printed: %1</source>
        <translation>Чертёж нельзя напечатать: %1</translation>
    </message>
    <message>
        <source>%1 seam allowance</source>
        <extracomment>Name of a new seam allowance: %1 is the name of its curve.</extracomment>
        <translation>%1 — припуск на шов</translation>
    </message>
    <message>
        <source>Add seam allowance</source>
        <translation>Добавить припуск на шов</translation>
    </message>
    <message>
        <source>Change seam allowance</source>
        <translation>Изменить припуск на шов</translation>
    </message>
    <message>
        <source>Detach seam allowance</source>
        <translation>Отвязать припуск на шов</translation>
    </message>
    <message>
        <source>no file name was given</source>
        <translation>не указано имя файла</translation>
    </message>
</context>
<context>
    <name>kontur::FunctionSplinePlot</name>
    <message>
        <source>Function values: “%1” is not a number.</source>
        <translation>Значения функции: «%1» — не число.</translation>
    </message>
    <message>
        <source>Function values: give between 2 and %1 numbers.</source>
        <translation>Значения функции: введите от 2 до %1 чисел.</translation>
    </message>
    <message>
        <source>Interval: “%1” is not a number.</source>
        <translation>Интервал: «%1» — не число.</translation>
    </message>
    <message>
        <source>Interval: give two numbers, the smaller first.</source>
        <translation>Интервал: введите два числа, сначала меньшее.</translation>
    </message>
    <message>
        <source>Knots: “%1” is not a number.</source>
        <translation>Узлы: «%1» — не число.</translation>
    </message>
    <message numerus="yes">
        <source>Knots: give %n number(s), one per function value.</source>
        <translation>
            <numerusform>Узлы: введите %n число, по одному на каждое значение функции.</numerusform>
            <numerusform>Узлы: введите %n числа, по одному на каждое значение функции.</numerusform>
            <numerusform>Узлы: введите %n чисел, по одному на каждое значение функции.</numerusform>
        </translation>
    </message>
    <message>
        <source>Knots: each knot must be greater than the one before.</source>
        <translation>Узлы: каждый узел должен быть больше предыдущего.</translation>
    </message>
    <message>
        <source>Derivatives: “%1” is not a number.</source>
        <translation>Производные: «%1» — не число.</translation>
    </message>
    <message numerus="yes">
        <source>Derivatives: give %n number(s), one per knot.</source>
        <translation>
            <numerusform>Производные: введите %n число, по одному на каждый узел.</numerusform>
            <numerusform>Производные: введите %n числа, по одному на каждый узел.</numerusform>
            <numerusform>Производные: введите %n чисел, по одному на каждый узел.</numerusform>
        </translation>
    </message>
    <message>
        <source>Derivatives: give two numbers, at the first and the last knot.</source>
        <translation>Производные: введите два числа — в первом и последнем узлах.</translation>
    </message>
    <message>
        <source>Values P at the inner knots: %1</source>
        <translation>Значения P во внутренних узлах: %1</translation>
    </message>
    <message>
        <source>Slopes y′ at the knots: %1</source>
        <translation>Наклоны y′ в узлах: %1</translation>
    </message>
    <message>
        <source>Polynomial of degree %1: it differs from the spline by up to %2.</source>
        <translation>Многочлен степени %1: отличается от сплайна не более чем на %2.</translation>
    </message>
    <message numerus="yes">
        <source>The polynomial is drawn for at most %n point(s).</source>
        <translation>
            <numerusform>Многочлен рисуется не более чем для %n точки.</numerusform>
            <numerusform>Многочлен рисуется не более чем для %n точек.</numerusform>
            <numerusform>Многочлен рисуется не более чем для %n точек.</numerusform>
        </translation>
    </message>
    <message>
        <source>polynomial</source>
        <extracomment>Legend label (noun): the interpolating polynomial drawn beside the spline.</extracomment>
        <translation>многочлен</translation>
    </message>
    <message>
        <source>spline</source>
        <extracomment>Legend label (noun): the spline.</extracomment>
        <translation>сплайн</translation>
    </message>
    <message>
        <source>Török&apos;s procedure needs evenly spaced knots: the classical system is drawn.</source>
        <translation>Методу Тёрёка нужны равномерно расположенные узлы: показано решение классической системы.</translation>
    </message>
    <message>
        <source>Török&apos;s half-size system and the classical system agree: their slopes differ by at most %1.</source>
        <translation>Система Тёрёка половинного размера и классическая система согласуются: их производные различаются не более чем на %1.</translation>
    </message>
    <message>
        <source>Add the function spline to the document</source>
        <translation>Добавить сплайн-функцию в документ</translation>
    </message>
    <message numerus="yes">
        <source>Knots: give %n number(s), four more than the number of values.</source>
        <translation>
            <numerusform>Узлы: введите %n число, на четыре больше, чем значений.</numerusform>
            <numerusform>Узлы: введите %n числа, на четыре больше, чем значений.</numerusform>
            <numerusform>Узлы: введите %n чисел, на четыре больше, чем значений.</numerusform>
        </translation>
    </message>
    <message>
        <source>Control values b: %1</source>
        <extracomment>b are the global B-spline&apos;s control values, as the course writes them (one per bell Bs).</extracomment>
        <translation>Управляющие значения b: %1</translation>
    </message>
    <message>
        <source>Török&apos;s half-size system and the classical system agree: their slopes differ by less than 10⁻¹⁵ (rounding).</source>
        <translation>Система Тёрёка половинного размера и классическая система согласуются: их производные различаются менее чем на 10⁻¹⁵ (округление).</translation>
    </message>
    <message>
        <source>P(%1) = %2</source>
        <extracomment>One value of the spline: P(1,5) = 0,075 (%1 is x, %2 the value).</extracomment>
        <translation>P(%1) = %2</translation>
    </message>
    <message>
        <source>Between the knots: %1</source>
        <extracomment>The spline&apos;s values halfway between the knots, e.g. &quot;P(1,5) = 0,075; P(2,5) = 1,175&quot;.</extracomment>
        <translation>Между узлами: %1</translation>
    </message>
</context>
<context>
    <name>kontur::PieceEdits</name>
    <message>
        <source>There is no other open composite curve to join.</source>
        <translation>Нет другой незамкнутой составной кривой для соединения.</translation>
    </message>
    <message>
        <source>No curve with fewer knots stays within that tolerance.</source>
        <translation>Ни одна кривая с меньшим числом узлов не укладывается в этот допуск.</translation>
    </message>
    <message>
        <source>Type a tolerance greater than zero.</source>
        <translation>Введите допуск больше нуля.</translation>
    </message>
    <message>
        <source>This works on composite curves that are not locked.</source>
        <translation>Это работает с незаблокированными составными кривыми.</translation>
    </message>
    <message>
        <source>Make line</source>
        <translation>Выпрямить сегмент</translation>
    </message>
    <message>
        <source>Join curves</source>
        <translation>Соединить кривые</translation>
    </message>
    <message>
        <source>Simplify curve</source>
        <translation>Упростить кривую</translation>
    </message>
    <message>
        <source>Extend curve</source>
        <translation>Продлить кривую</translation>
    </message>
</context>
<context>
    <name>kontur::PieceMarkEdits</name>
    <message>
        <source>A pattern piece is a closed curve: close the curve first.</source>
        <translation>Деталь выкройки — замкнутая кривая: сначала замкните кривую.</translation>
    </message>
    <message>
        <source>Select a pattern piece first.</source>
        <translation>Сначала выберите деталь выкройки.</translation>
    </message>
    <message>
        <source>Type how many to cut: a whole number from 1 up.</source>
        <translation>Введите, сколько кроить: целое число от 1.</translation>
    </message>
    <message>
        <source>The two points are too close together: tap two points farther apart.</source>
        <translation>Две точки слишком близко: коснитесь двух точек подальше друг от друга.</translation>
    </message>
    <message>
        <source>There is no mark there.</source>
        <translation>Там нет метки.</translation>
    </message>
    <message>
        <source>Make a pattern piece</source>
        <translation>Сделать деталью выкройки</translation>
    </message>
    <message>
        <source>No longer a pattern piece</source>
        <translation>Больше не деталь выкройки</translation>
    </message>
    <message>
        <source>Set the piece&apos;s size</source>
        <translation>Задать размер детали</translation>
    </message>
    <message>
        <source>Set how many to cut</source>
        <translation>Задать, сколько кроить</translation>
    </message>
    <message>
        <source>Set the piece&apos;s material</source>
        <translation>Задать материал детали</translation>
    </message>
    <message>
        <source>Draw the grainline</source>
        <translation>Провести долевую нить</translation>
    </message>
    <message>
        <source>Place on fold</source>
        <translation>Положить на сгиб</translation>
    </message>
    <message>
        <source>Add a notch</source>
        <translation>Добавить надсечку</translation>
    </message>
    <message>
        <source>Move a notch</source>
        <translation>Сдвинуть надсечку</translation>
    </message>
    <message>
        <source>Change a notch</source>
        <translation>Изменить надсечку</translation>
    </message>
    <message>
        <source>Add a drill hole</source>
        <translation>Добавить пробивку</translation>
    </message>
    <message>
        <source>Move a drill hole</source>
        <translation>Сдвинуть пробивку</translation>
    </message>
    <message>
        <source>Delete a mark</source>
        <translation>Удалить метку</translation>
    </message>
</context>
<context>
    <name>kontur::PracticumPlot</name>
    <message>
        <source>The end points have the same x: there is no function segment.</source>
        <translation>У концевых точек одинаковый x: непараметрический сегмент построить нельзя.</translation>
    </message>
    <message>
        <source>A vertical guide vector has no slope dy/dx: a function segment needs one.</source>
        <translation>У вертикального направляющего вектора нет наклона dy/dx, а он нужен непараметрическому сегменту.</translation>
    </message>
    <message>
        <source>t = x1 − x0 = %1; k0 = %2; k1 = %3; a3 = %4; a4 = %5</source>
        <translation>t = x1 − x0 = %1; k0 = %2; k1 = %3; a3 = %4; a4 = %5</translation>
    </message>
    <message>
        <source>The end points coincide or a guide vector has no length.</source>
        <translation>Концевые точки совпадают или направляющий вектор имеет нулевую длину.</translation>
    </message>
    <message>
        <source>t2 = |P1 − P0| = %1; P0′ = %2; P1′ = %3; a3 = %4; a4 = %5</source>
        <translation>t2 = |P1 − P0| = %1; P0′ = %2; P1′ = %3; a3 = %4; a4 = %5</translation>
    </message>
    <message>
        <source>Two neighbouring points coincide or a guide vector has no length.</source>
        <translation>Две соседние точки совпадают или направляющий вектор имеет нулевую длину.</translation>
    </message>
    <message>
        <source>Chords T: %1
Tangents K: %2</source>
        <extracomment>Two lines of figures: %1 the chord lengths T, %2 the tangent lengths K of the segments (numbers).</extracomment>
        <translation>Хорды T: %1
Касательные K: %2</translation>
    </message>
</context>
<context>
    <name>kontur::SeamWidths</name>
    <message>
        <source>The piece has no seam allowance yet: add one first.</source>
        <translation>У детали ещё нет припуска на шов: сначала добавьте его.</translation>
    </message>
    <message>
        <source>Tap a seam of the piece first.</source>
        <translation>Сначала коснитесь шва детали.</translation>
    </message>
    <message>
        <source>Type the seam allowance: a number from 0 up.</source>
        <translation>Введите припуск на шов: число от 0 и больше.</translation>
    </message>
    <message>
        <source>The seam allowance cannot be that wide on this piece.</source>
        <translation>Припуск на шов не может быть таким широким для этой детали.</translation>
    </message>
    <message>
        <source>Set a seam&apos;s allowance</source>
        <translation>Задать припуск на шов</translation>
    </message>
    <message>
        <source>Set a hem&apos;s corners</source>
        <translation>Задать углы подгибки низа</translation>
    </message>
</context>
<context>
    <name>kontur::TraceController</name>
    <message>
        <source>Calibrate background</source>
        <translation>Калибровать фон</translation>
    </message>
    <message>
        <source>The tolerance must be a positive number.</source>
        <translation>Допуск должен быть положительным числом.</translation>
    </message>
    <message>
        <source>Draw along the contour with one finger, a stylus or the mouse.</source>
        <translation>Ведите вдоль контура одним пальцем, стилусом или мышью.</translation>
    </message>
    <message>
        <source>The stroke could not be fitted.</source>
        <translation>Не удалось аппроксимировать штрих.</translation>
    </message>
    <message>
        <source>Traced %1</source>
        <extracomment>Automatic name of a curve drawn freehand over the picture: %1 is a running number.</extracomment>
        <translation>Обведённая %1</translation>
    </message>
    <message>
        <source>Freehand curve</source>
        <translation>Кривая от руки</translation>
    </message>
    <message>
        <source>Load a background picture first.</source>
        <translation>Сначала загрузите фоновое изображение.</translation>
    </message>
    <message>
        <source>Tap a knot of the curve.</source>
        <translation>Коснитесь узла кривой.</translation>
    </message>
    <message>
        <source>Tap a curve.</source>
        <translation>Коснитесь кривой.</translation>
    </message>
    <message>
        <source>Tap a second, different curve.</source>
        <translation>Коснитесь второй, другой кривой.</translation>
    </message>
    <message>
        <source>This kind of curve has no knots to measure between.</source>
        <translation>У кривой этого вида нет узлов, между которыми можно измерять.</translation>
    </message>
    <message>
        <source>These curves cannot be compared.</source>
        <translation>Эти кривые нельзя сравнить.</translation>
    </message>
    <message>
        <source>Tap two points on the picture first.</source>
        <translation>Сначала коснитесь двух точек на изображении.</translation>
    </message>
    <message>
        <source>Type the real distance between the two points as a positive number.</source>
        <translation>Введите реальное расстояние между двумя точками положительным числом.</translation>
    </message>
    <message>
        <source>The background is locked. Unlock it to calibrate again.</source>
        <translation>Фон заблокирован. Разблокируйте его, чтобы откалибровать заново.</translation>
    </message>
    <message>
        <source>Choose mm, cm or in.</source>
        <translation>Выберите мм, см или дюймы.</translation>
    </message>
    <message>
        <source>The two points must be different.</source>
        <translation>Две точки должны различаться.</translation>
    </message>
    <message>
        <source>Curve &quot;%1&quot; cannot be turned; calibrate without aligning.</source>
        <translation>Кривую «%1» нельзя повернуть; калибруйте без выравнивания.</translation>
    </message>
    <message>
        <source>Draw along the contour with one finger, a stylus or the mouse; two fingers zoom.</source>
        <translation>Ведите вдоль контура одним пальцем, стилусом или мышью; двумя пальцами — масштаб.</translation>
    </message>
    <message>
        <source>Tap two points on the picture whose real distance you know.</source>
        <translation>Коснитесь двух точек изображения, реальное расстояние между которыми известно.</translation>
    </message>
    <message>
        <source>Type the real distance between the two points.</source>
        <translation>Введите реальное расстояние между двумя точками.</translation>
    </message>
    <message>
        <source>Tap two points to measure the straight distance.</source>
        <translation>Коснитесь двух точек, чтобы измерить расстояние по прямой.</translation>
    </message>
    <message>
        <source>Tap two knots of one curve to measure the length along it.</source>
        <translation>Коснитесь двух узлов одной кривой, чтобы измерить длину вдоль неё.</translation>
    </message>
    <message>
        <source>Tap the traced curve, then the reference curve.</source>
        <translation>Коснитесь обведённой кривой, затем эталонной.</translation>
    </message>
    <message>
        <source>Drag the picture to move it; two fingers zoom.</source>
        <translation>Перетащите изображение, чтобы переместить его; двумя пальцами — масштаб.</translation>
    </message>
    <message>
        <source>The background is locked. Unlock it to move it.</source>
        <translation>Фон заблокирован. Разблокируйте его, чтобы переместить.</translation>
    </message>
    <message>
        <source>Tap the four corners of the rectangle first.</source>
        <translation>Сначала коснитесь четырёх углов прямоугольника.</translation>
    </message>
    <message>
        <source>Type the rectangle&apos;s width and height as positive numbers.</source>
        <translation>Введите ширину и высоту прямоугольника положительными числами.</translation>
    </message>
    <message>
        <source>The picture has a perspective calibration. Clear it to calibrate by two points.</source>
        <translation>У изображения есть калибровка перспективы. Сбросьте её, чтобы калибровать по двум точкам.</translation>
    </message>
    <message>
        <source>There the corners would not make a rectangle; the corner stays where it was.</source>
        <translation>Там углы не образовали бы прямоугольник; угол остаётся на месте.</translation>
    </message>
    <message>
        <source>Drag a corner onto the rectangle&apos;s corner in the picture, or tap four new corners.</source>
        <translation>Перетащите угол на угол прямоугольника на изображении или коснитесь четырёх новых углов.</translation>
    </message>
    <message>
        <source>Tap the four corners of a rectangle whose size you know, in any order.</source>
        <translation>Коснитесь в любом порядке четырёх углов прямоугольника, размеры которого известны.</translation>
    </message>
    <message>
        <source>Choose the rectangle&apos;s size and apply; drag a corner to refine it.</source>
        <translation>Выберите размер прямоугольника и примените; перетащите угол, чтобы уточнить его.</translation>
    </message>
    <message>
        <source>Calibrate perspective</source>
        <translation>Калибровать перспективу</translation>
    </message>
    <message>
        <source>Refine perspective corner</source>
        <translation>Уточнить угол перспективы</translation>
    </message>
    <message>
        <source>Outline %1</source>
        <extracomment>Automatic name of a curve traced along a piece&apos;s outline in the photo: %1 is a running number.</extracomment>
        <translation>Контур %1</translation>
    </message>
    <message>
        <source>Trace outline</source>
        <translation>Обвести контур</translation>
    </message>
    <message>
        <source>The background picture cannot be read.</source>
        <translation>Не удаётся прочитать фоновое изображение.</translation>
    </message>
    <message>
        <source>No sheet found in the picture (a white rectangle with four straight, clear edges). Tap its four corners instead.</source>
        <translation>Лист на изображении не найден (белый прямоугольник с четырьмя прямыми чёткими краями). Вместо этого коснитесь четырёх его углов.</translation>
    </message>
    <message>
        <source>No corner found near the mark; it stays where you dropped it.</source>
        <translation>Рядом с меткой угол не найден; она остаётся там, где вы её отпустили.</translation>
    </message>
    <message>
        <source>The calibration may be off by %1 mm at the far side of the picture. Find the sheet again or refine its corners.</source>
        <translation>На дальней стороне изображения калибровка может ошибаться на %1 мм. Найдите лист снова или уточните его углы.</translation>
    </message>
    <message>
        <source>No pattern piece found there. Tap inside a piece that stands out from the table.</source>
        <translation>Там не найдена деталь выкройки. Коснитесь внутри детали, которая выделяется на фоне стола.</translation>
    </message>
    <message>
        <source>The outline could not be made into a curve.</source>
        <translation>Не удалось превратить контур в кривую.</translation>
    </message>
    <message>
        <source>No edge found along the stroke; it was fitted as drawn.</source>
        <translation>Вдоль штриха край не найден; он аппроксимирован так, как нарисован.</translation>
    </message>
    <message>
        <source>Tap inside a pattern piece on the picture to trace its outline.</source>
        <translation>Коснитесь внутри детали выкройки на изображении, чтобы обвести её контур.</translation>
    </message>
    <message>
        <source>The four points are not the corners of a rectangle seen in the picture. Tap them again.</source>
        <translation>Эти четыре точки не являются углами прямоугольника на изображении. Коснитесь их заново.</translation>
    </message>
    <message>
        <source>The sheet in the picture is not flat: its edges bend. Lay it flat and take the photo again, or tap its four corners.</source>
        <translation>Лист на изображении лежит неровно: его края изогнуты. Положите его ровно и сфотографируйте снова или коснитесь четырёх его углов.</translation>
    </message>
    <message>
        <source>The rectangle found is about %1 : 1, the chosen one %2 : 1. Choose the sheet&apos;s size, or tap its four corners.</source>
        <extracomment>%1 and %2 are proportions, long side to short side, such as 2.35 and 1.41.</extracomment>
        <translation>Найденный прямоугольник — примерно %1 : 1, а выбранный — %2 : 1. Выберите размер листа или коснитесь четырёх его углов.</translation>
    </message>
</context>
<context>
    <name>kontur::cli</name>
    <message>
        <source>%1: several curves in the file (%2); the points of the first one (line %3) are read</source>
        <translation>%1: в файле несколько кривых (%2); читаются точки первой из них (строка %3)</translation>
    </message>
    <message>
        <source>unexpected argument &quot;%1&quot;</source>
        <translation>неожиданный аргумент «%1»</translation>
    </message>
    <message>
        <source>--in FILE is required</source>
        <translation>требуется --in ФАЙЛ</translation>
    </message>
    <message>
        <source>Fit a cubic Bézier curve to points (one &quot;x y&quot; per line).</source>
        <translation>Построить кубическую кривую Безье по точкам (одна пара «x y» в строке).</translation>
    </message>
    <message>
        <source>interpolate (exactly 4 points) or least-squares.</source>
        <translation>interpolate (ровно 4 точки) или least-squares.</translation>
    </message>
    <message>
        <source>uniform, chord or centripetal.</source>
        <translation>uniform, chord или centripetal.</translation>
    </message>
    <message>
        <source>The points file.</source>
        <translation>Файл с точками.</translation>
    </message>
    <message>
        <source>unknown --method &quot;%1&quot; (interpolate or least-squares)</source>
        <translation>неизвестный --method «%1» (interpolate или least-squares)</translation>
    </message>
    <message>
        <source>unknown --param &quot;%1&quot; (uniform, chord or centripetal)</source>
        <translation>неизвестный --param «%1» (uniform, chord или centripetal)</translation>
    </message>
    <message>
        <source>--reparameterize needs a non-negative integer</source>
        <translation>для --reparameterize нужно неотрицательное целое число</translation>
    </message>
    <message>
        <source>%1: %2 points; interpolate needs exactly 4</source>
        <extracomment>%1 is a file name, %2 the number of points in it.</extracomment>
        <translation>%1: точек: %2; для interpolate нужно ровно 4</translation>
    </message>
    <message>
        <source>The control points file.</source>
        <translation>Файл с опорными точками.</translation>
    </message>
    <message>
        <source>Elevate the degree R times.</source>
        <translation>Повысить степень R раз.</translation>
    </message>
    <message>
        <source>Evaluate at t1,t2,…</source>
        <translation>Вычислить при t1,t2,…</translation>
    </message>
    <message>
        <source>Arc length to this absolute accuracy.</source>
        <translation>Длина дуги с этой абсолютной точностью.</translation>
    </message>
    <message>
        <source>Nearest point to x,y.</source>
        <translation>Ближайшая точка к x,y.</translation>
    </message>
    <message>
        <source>The tight bounding box.</source>
        <translation>Точный охватывающий прямоугольник.</translation>
    </message>
    <message>
        <source>--elevate needs an integer from 0 to 10000</source>
        <translation>для --elevate нужно целое число от 0 до 10000</translation>
    </message>
    <message>
        <source>--at needs numbers separated by commas</source>
        <translation>для --at нужны числа через запятую</translation>
    </message>
    <message>
        <source>--length needs a positive accuracy</source>
        <translation>для --length нужна положительная точность</translation>
    </message>
    <message>
        <source>--nearest needs x,y</source>
        <translation>для --nearest нужно x,y</translation>
    </message>
    <message>
        <source>Build the composite curve through the knots in the file.</source>
        <translation>Построить составную кривую через узлы из файла.</translation>
    </message>
    <message>
        <source>The knots file.</source>
        <translation>Файл с узлами.</translation>
    </message>
    <message>
        <source>Close the curve.</source>
        <translation>Замкнуть кривую.</translation>
    </message>
    <message>
        <source>Relative tolerance of the continuity report (default 1e-9).</source>
        <translation>Относительный допуск отчёта о непрерывности (по умолчанию 1e-9).</translation>
    </message>
    <message>
        <source>--tolerance needs a non-negative number</source>
        <translation>для --tolerance нужно неотрицательное число</translation>
    </message>
    <message numerus="yes">
        <source>expected %n file name(s), got %1</source>
        <translation>
            <numerusform>ожидалось %n имя файла, получено %1</numerusform>
            <numerusform>ожидалось %n имени файла, получено %1</numerusform>
            <numerusform>ожидалось %n имён файлов, получено %1</numerusform>
        </translation>
    </message>
    <message>
        <source>The input file.</source>
        <translation>Входной файл.</translation>
    </message>
    <message>
        <source>The output file.</source>
        <translation>Выходной файл.</translation>
    </message>
    <message>
        <source>Kind of curve for points without one (default composite).</source>
        <translation>Вид кривой для точек без указанного вида (по умолчанию composite).</translation>
    </message>
    <message>
        <source>Parameterization for fitted kinds (default chord).</source>
        <translation>Параметризация для аппроксимируемых видов (по умолчанию chord).</translation>
    </message>
    <message>
        <source>Write only curve N (0-based).</source>
        <translation>Записать только кривую N (с 0).</translation>
    </message>
    <message>
        <source>unknown --kind &quot;%1&quot;</source>
        <translation>неизвестный --kind «%1»</translation>
    </message>
    <message>
        <source>--curve needs a curve number from 0 to %1</source>
        <translation>для --curve нужен номер кривой от 0 до %1</translation>
    </message>
    <message>
        <source>Describe the curves of a file as JSON: kinds, point counts, lengths, bounding boxes, continuity.</source>
        <translation>Описание кривых файла в JSON: виды, число точек, длины, охватывающие прямоугольники, непрерывность.</translation>
    </message>
    <message>
        <source>Absolute accuracy of the lengths (default 1e-9).</source>
        <translation>Абсолютная точность длин (по умолчанию 1e-9).</translation>
    </message>
    <message>
        <source>--accuracy needs a positive number</source>
        <translation>для --accuracy нужно положительное число</translation>
    </message>
    <message>
        <source>
For every command:
  --lang CODE  the language of help and messages: %1 (default: the system&apos;s)
</source>
        <translation>
Для всех команд:
  --lang КОД   язык справки и сообщений: %1 (по умолчанию системный)
</translation>
    </message>
    <message>
        <source>kontur-cli: unknown command &quot;%1&quot;</source>
        <translation>kontur-cli: неизвестная команда «%1»</translation>
    </message>
    <message>
        <source>%1:%2: expected two numbers &quot;x y&quot;, got &quot;%3&quot;</source>
        <translation>%1:%2: ожидались два числа «x y», получено «%3»</translation>
    </message>
    <message>
        <source>%1: cannot read the file: %2</source>
        <translation>%1: не удаётся прочитать файл: %2</translation>
    </message>
    <message>
        <source>The family (see above).</source>
        <translation>Семейство (см. выше).</translation>
    </message>
    <message>
        <source>uniform, chord (default) or centripetal.</source>
        <translation>uniform, chord (по умолчанию) или centripetal.</translation>
    </message>
    <message>
        <source>A function spline y(x) over the points&apos; increasing x; --at then takes x values and points are [x, y].</source>
        <translation>Сплайн-функция y(x) по возрастающим x точек; тогда --at принимает значения x, а точки имеют вид [x, y].</translation>
    </message>
    <message>
        <source>Start tangent x,y (clamped, global-bspline; default the first chord).</source>
        <translation>Начальный направляющий вектор x,y (clamped, global-bspline; по умолчанию первая хорда).</translation>
    </message>
    <message>
        <source>End tangent x,y (clamped, global-bspline; default the last chord).</source>
        <translation>Конечный направляющий вектор x,y (clamped, global-bspline; по умолчанию последняя хорда).</translation>
    </message>
    <message>
        <source>--kind must be one of %1</source>
        <translation>--kind должен быть одним из %1</translation>
    </message>
    <message>
        <source>--%1 needs x,y</source>
        <translation>для --%1 нужно x,y</translation>
    </message>
    <message>
        <source>--order needs an integer</source>
        <translation>для --order нужно целое число</translation>
    </message>
    <message>
        <source>a function B-spline takes a knot vector and control values, not points: drop --function</source>
        <translation>B-сплайну в виде функции y(x) нужны узловой вектор и управляющие значения, а не точки: уберите --function</translation>
    </message>
    <message>
        <source>at least 2 points are needed</source>
        <translation>нужно не меньше 2 точек</translation>
    </message>
    <message>
        <source>a vertical or zero end tangent has no slope</source>
        <translation>у вертикального или нулевого концевого направляющего вектора нет наклона</translation>
    </message>
    <message>
        <source>--knots needs open-uniform, uniform or numbers separated by commas</source>
        <translation>для --knots нужно open-uniform, uniform или числа через запятую</translation>
    </message>
    <message>
        <source>could not compute &quot;%1&quot; as a finite number: the numbers involved exceed the range of double precision</source>
        <translation>не удаётся вычислить «%1» как конечное число: числа выходят за пределы диапазона двойной точности</translation>
    </message>
    <message>
        <source>unknown --solver &quot;%1&quot; (classical or torok)</source>
        <translation>неизвестный --solver «%1» (classical или torok)</translation>
    </message>
    <message>
        <source>--solver is for --kind clamped</source>
        <translation>--solver применяется только с --kind clamped</translation>
    </message>
    <message>
        <source>Török&apos;s procedure needs evenly spaced knots: use --param uniform or --function</source>
        <translation>Методу Тёрёка нужны равномерно расположенные узлы: используйте --param uniform или --function</translation>
    </message>
    <message>
        <source>a contour curve is drawn through its points in the plane: drop --function</source>
        <translation>контурная кривая строится по точкам на плоскости: уберите --function</translation>
    </message>
    <message>
        <source>--paper needs a4 or letter</source>
        <translation>для --paper нужно a4 или letter</translation>
    </message>
    <message>
        <source>--orientation needs auto, portrait or landscape</source>
        <translation>для --orientation нужно auto, portrait или landscape</translation>
    </message>
    <message>
        <source>--overlap needs millimetres from 0 to 50</source>
        <translation>для --overlap нужно число миллиметров от 0 до 50</translation>
    </message>
    <message>
        <source>PDF: the paper, a4 or letter (default a4).</source>
        <translation>PDF: бумага, a4 или letter (по умолчанию a4).</translation>
    </message>
    <message>
        <source>PDF: auto (the one with fewer pages), portrait or landscape (default auto).</source>
        <translation>PDF: auto (та, где меньше листов), portrait или landscape (по умолчанию auto).</translation>
    </message>
    <message>
        <source>PDF: millimetres neighbouring pages repeat (default 10).</source>
        <translation>PDF: сколько миллиметров повторяют соседние листы (по умолчанию 10).</translation>
    </message>
    <message>
        <source>Add seam allowances: the offset of each curve (or of curve N) at a distance, written after the
input&apos;s curves. In a .kontur output each allowance keeps its link to its curve.</source>
        <translation>Добавить припуски на шов: эквидистанту каждой кривой (или кривой N) на заданном расстоянии,
записанную после кривых входа. В выходном файле .kontur каждый припуск сохраняет связь со своей кривой.</translation>
    </message>
    <message>
        <source>Offset only curve N (0-based).</source>
        <translation>Сдвинуть только кривую N (с 0).</translation>
    </message>
    <message>
        <source>Distance in the document&apos;s units (default 1 cm).</source>
        <translation>Расстояние в единицах документа (по умолчанию 1 см).</translation>
    </message>
    <message>
        <source>outside, inside, left or right (default outside).</source>
        <translation>outside, inside, left или right (по умолчанию outside).</translation>
    </message>
    <message>
        <source>Corners: miter, bevel or round (default miter).</source>
        <translation>Углы: miter, bevel или round (по умолчанию miter).</translation>
    </message>
    <message>
        <source>Longest miter from the corner (default 3 cm).</source>
        <translation>Наибольшая длина острого угла от вершины (по умолчанию 3 см).</translation>
    </message>
    <message>
        <source>Largest error of the offset (default 0.05 mm).</source>
        <translation>Наибольшая погрешность эквидистанты (по умолчанию 0,05 мм).</translation>
    </message>
    <message>
        <source>--distance needs a positive number</source>
        <translation>для --distance нужно положительное число</translation>
    </message>
    <message>
        <source>--miter-limit needs a number of at least 0</source>
        <translation>для --miter-limit нужно число не меньше 0</translation>
    </message>
    <message>
        <source>--tolerance needs a positive number</source>
        <translation>для --tolerance нужно положительное число</translation>
    </message>
    <message>
        <source>unknown --side &quot;%1&quot;</source>
        <translation>неизвестный --side «%1»</translation>
    </message>
    <message>
        <source>unknown --join &quot;%1&quot;</source>
        <translation>неизвестный --join «%1»</translation>
    </message>
    <message>
        <source>%1: unknown file type (%2)</source>
        <translation>%1: неизвестный тип файла (%2)</translation>
    </message>
    <message>
        <source>Convert between points text (.txt), CSV, Kontur documents (.kontur), SVG and DXF, by extension.
A .txt output is appended to, never overwritten; other outputs are replaced atomically.
A .pdf output prints the visible curves at true size over A4 or Letter pages (a first page with
a 10 cm test square and the overview, then the pages to tape together); the document is kept
inside, so a PDF Kontur wrote converts back.</source>
        <translation>Преобразование между текстом точек (.txt), CSV, документами Kontur (.kontur), SVG и DXF по расширению.
Вывод .txt дописывается, а не перезаписывается; остальные файлы заменяются атомарно.
Вывод .pdf печатает видимые кривые в реальном размере на листах A4 или Letter (первый лист с
контрольным квадратом 10 см и общим видом, затем листы для склейки); документ хранится внутри,
поэтому PDF, записанный Kontur, преобразуется обратно.</translation>
    </message>
    <message>
        <source>DXF output: spline (exact Bézier control points, default) or polyline (flattened).</source>
        <translation>Вывод DXF: spline (сплайны с точными опорными точками Безье, по умолчанию) или polyline (ломаные).</translation>
    </message>
    <message>
        <source>DXF polyline output: largest distance from the curves, in the document&apos;s units (default 0.05 mm).</source>
        <translation>Вывод DXF ломаными: наибольшее расстояние от кривых в единицах документа (по умолчанию 0,05 мм).</translation>
    </message>
    <message>
        <source>unknown --dxf &quot;%1&quot; (spline or polyline)</source>
        <translation>неизвестный --dxf «%1» (spline — сплайны или polyline — ломаные)</translation>
    </message>
    <message>
        <source>A .txt, .csv, .kontur, .svg or .dxf file.</source>
        <translation>Файл .txt, .csv, .kontur, .svg или .dxf.</translation>
    </message>
    <message>
        <source>The photo (PNG, JPEG, PGM, ...).</source>
        <translation>Фотография (PNG, JPEG, PGM, ...).</translation>
    </message>
    <message>
        <source>The sheet&apos;s size: a4, a3, letter or WxH with mm (default), cm or in.</source>
        <translation>Размер листа: a4, a3, letter или WxH с mm (по умолчанию), cm или in.</translation>
    </message>
    <message>
        <source>Approximate corners in photo pixels, x,y;x,y;x,y;x,y in any order: the edges are searched near them.</source>
        <translation>Приблизительные углы в пикселях снимка, x,y;x,y;x,y;x,y в любом порядке: края ищутся рядом с ними.</translation>
    </message>
    <message>
        <source>--sheet needs a4, a3, letter or WxH[mm|cm|in], got &quot;%1&quot;</source>
        <translation>для --sheet нужно a4, a3, letter или WxH[mm|cm|in], получено «%1»</translation>
    </message>
    <message>
        <source>--corners needs four points x,y separated by semicolons or spaces</source>
        <translation>для --corners нужны четыре точки x,y, разделённые точкой с запятой или пробелами</translation>
    </message>
    <message>
        <source>%1: cannot read the photo</source>
        <translation>%1: не удаётся прочитать фотографию</translation>
    </message>
    <message>
        <source>Trace a pattern photographed beside a reference sheet: the sheet is found (its corners to a
fraction of a pixel), the photo rectified into the sheet&apos;s plane and every pattern piece&apos;s outline
written as a closed composite curve in mm to OUT.kontur, with the photo as its calibrated
background. --json prints the corners, the calibration&apos;s estimated error and each curve&apos;s knots.</source>
        <translation>Обвести выкройку, сфотографированную рядом с эталонным листом: лист находится (его углы с точностью
до доли пикселя), фото выпрямляется в плоскость листа, и контур каждой детали выкройки
записывается в OUT.kontur как замкнутая составная кривая в мм, с фото как откалиброванным фоновым
изображением. --json выводит углы, оценку погрешности калибровки и узлы каждой кривой.</translation>
    </message>
    <message>
        <source>The document to write (.kontur).</source>
        <translation>Документ для записи (.kontur).</translation>
    </message>
    <message>
        <source>Print the sheet&apos;s corners, the calibration error and the outlines&apos; knots as JSON.</source>
        <translation>Вывести углы листа, погрешность калибровки и узлы контуров в JSON.</translation>
    </message>
    <message>
        <source>trace needs an output file OUT.kontur, or --json for the sheet&apos;s corners</source>
        <translation>для обводки (trace) нужен выходной файл OUT.kontur или --json для углов листа</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>%1: curve %2: %3</source>
        <translation>%1: кривая %2: %3</translation>
    </message>
    <message>
        <source>no such file</source>
        <translation>файл не найден</translation>
    </message>
    <message>
        <source>its symbolic links form a loop</source>
        <translation>его символические ссылки образуют цикл</translation>
    </message>
    <message>
        <source>permission denied</source>
        <translation>доступ запрещён</translation>
    </message>
    <message>
        <source>it is a folder, not a file</source>
        <translation>это папка, а не файл</translation>
    </message>
    <message>
        <source>it is a named pipe (FIFO), not a regular file</source>
        <translation>это именованный канал (FIFO), а не обычный файл</translation>
    </message>
    <message>
        <source>it is a device, not a regular file</source>
        <translation>это устройство, а не обычный файл</translation>
    </message>
    <message>
        <source>it is not a regular file</source>
        <translation>это не обычный файл</translation>
    </message>
    <message>
        <source>%1: a CSV file holds the points of one curve; the input has %2: choose one with --curve N</source>
        <translation>%1: CSV-файл содержит точки одной кривой; во входных данных их %2: выберите одну с помощью --curve N</translation>
    </message>
    <message>
        <source>%1: unknown language &quot;%2&quot;; choose one of: %3.</source>
        <extracomment>%1 is the program (kontur or kontur-cli), %2 the language code asked for, %3 the codes there are.</extracomment>
        <translation>%1: неизвестный язык «%2»; выберите один из: %3.</translation>
    </message>
    <message>
        <source>Rounds of parameter correction (default 0: the parameters are used as computed).</source>
        <translation>Число итераций уточнения параметров (по умолчанию 0: параметры используются так, как вычислены).</translation>
    </message>
    <message>
        <source>%1: %2 points; a least-squares cubic needs at least 4</source>
        <translation>%1: точек %2; кубической кривой по МНК нужно не менее 4</translation>
    </message>
    <message>
        <source>Work with the Bézier curve whose control points are in the file. Prints the control points (JSON key control_points) when --elevate is given or when nothing else is asked for.</source>
        <translation>Работа с кривой Безье, опорные точки которой записаны в файле. Выводит опорные точки (ключ JSON control_points) при --elevate или если ничего другого не запрошено.</translation>
    </message>
    <message>
        <source>%1: %2 points; a Bézier curve needs at least 2</source>
        <extracomment>%1 is a file name, %2 the number of points in it.</extracomment>
        <translation>%1: точек %2; кривой Безье нужно не менее 2</translation>
    </message>
    <message>
        <source>%1: %2 points; a closed composite curve needs at least 3</source>
        <extracomment>%1 is a file name, %2 the number of points in it.</extracomment>
        <translation>%1: точек %2; замкнутой составной кривой нужно не менее 3</translation>
    </message>
    <message>
        <source>%1: %2 points; a composite curve needs at least 2</source>
        <translation>%1: точек %2; составной кривой нужно не менее 2</translation>
    </message>
    <message>
        <source>clamped on evenly spaced knots (--function over evenly spaced x, or --param uniform): classical (default, k - 2 unknowns) or torok (Török&apos;s half-size system); prints the JSON key &quot;solverDifference&quot;: the largest difference of the derivatives from the other solver.</source>
        <translation>clamped на равномерно расположенных узлах (--function по равномерно расположенным x или --param uniform): classical (по умолчанию, k - 2 неизвестных) или torok (система Тёрёка половинного размера); выводит ключ JSON &quot;solverDifference&quot; — наибольшее различие производных с другим методом.</translation>
    </message>
    <message>
        <source>Evaluate at u1,u2,… (a negative first value needs the = form: --at=-1,0.5).</source>
        <translation>Вычислить при u1, u2, … (отрицательное первое значение пишите через =: --at=-1,0.5).</translation>
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
        <translation>Использование: kontur-cli &lt;команда&gt; [параметры]   (kontur-cli &lt;команда&gt; --help покажет её параметры)
Командная утилита Kontur: кривые Безье и сплайны без окна.

Команды:
  fit        кубическая кривая через 4 точки или по методу наименьших квадратов через n &gt;= 4 точек
  bezier     вычисление, повышение степени, измерение и запросы для кривой Безье любой степени
  composite  составная кривая через узлы с отчётом о непрерывности
  spline     кривая любого вида через точки, построенная как в приложении (bezier,
             composite, natural, clamped, hermite, bspline, function-spline, contour, …)
  convert    преобразовать IN OUT между текстом точек (.txt), CSV, .kontur, SVG, DXF и PDF (по расширению;
             вывод PDF — выкройка, напечатанная в реальном размере)
  info       кривые файла в JSON: виды, длины, охватывающий прямоугольник, непрерывность
  offset     припуски на шов: эквидистанты кривых IN OUT на заданном расстоянии, снаружи или внутри
  trace      обвести выкройку, сфотографированную рядом с эталонным листом, в документ в мм
  bench      измерить время операции геометрического ядра (для разработчиков)

Во входных файлах по одной паре «x y» в строке; «#» начинает комментарий. Вывод — JSON в stdout;
ошибки — в stderr с кодом 1 (неверные данные) или 2 (неверный вызов).
</translation>
    </message>
    <message>
        <source>The curve of a kind through the points of a file (one &quot;x y&quot; per line), built by the same function as the app&apos;s curve of that kind: bezier (the points are its control points), interpolating, least-squares, composite, natural, clamped, not-a-knot, periodic, catmull-rom, hermite, bspline (the points are its control polygon), global-bspline, polynomial, function-spline (the natural spline y(x)) or contour (Bézier pieces joined at the midpoints of pairs of points). Prints {&quot;knots&quot;: parameter of each point (the knot vector for bspline; 0, 1, … one per piece for bezier, interpolating, least-squares, composite and contour), &quot;segments&quot;: Bézier control points of each piece, &quot;points&quot;: [u, x, y] at --at}. Parameters are unnormalised: uniform 0, 1, 2, …; chord the cumulative chord length; centripetal the cumulative square roots.</source>
        <translation>Кривая заданного вида через точки файла (одна пара «x y» в строке), построенная той же функцией, что и кривая этого вида в приложении: bezier (точки — её опорные точки), interpolating (интерполяционная кубическая кривая), least-squares, composite, natural, clamped, not-a-knot, periodic, catmull-rom, hermite, bspline (точки — его опорный многоугольник), global-bspline, polynomial, function-spline (естественный сплайн y(x)) или contour (куски Безье, соединённые в серединах пар точек). Выводит {&quot;knots&quot;: параметр каждой точки (для bspline — узловой вектор; для bezier, interpolating, least-squares, composite и contour — 0, 1, …, по одному на кусок), &quot;segments&quot;: опорные точки Безье каждого куска, &quot;points&quot;: [u, x, y] при --at}. Параметры не нормированы: uniform 0, 1, 2, …; chord — накопленная длина хорд; centripetal — накопленные квадратные корни.</translation>
    </message>
    <message>
        <source>B-spline order k, 2 to 10 (default as in the app: 4, cubic, or the number of points when fewer).</source>
        <translation>Порядок B-сплайна k, от 2 до 10 (по умолчанию как в приложении: 4, кубический, или число точек, если их меньше).</translation>
    </message>
    <message>
        <source>B-spline knot vector: open-uniform (default, the app&apos;s knots), uniform, or u0,u1,… (n + k values).</source>
        <translation>Узловой вектор B-сплайна: open-uniform (по умолчанию, узлы приложения), uniform или u0,u1,… (n + k значений).</translation>
    </message>
    <message>
        <source>hermite: a file with one tangent &quot;x y&quot; per point (default Catmull–Rom tangents, as in the app).</source>
        <translation>hermite: файл с одним направляющим вектором «x y» на точку (по умолчанию направляющие векторы Катмулла–Рома, как в приложении).</translation>
    </message>
    <message>
        <source>composite: the closed curve (as Close curve makes it in the app).</source>
        <translation>composite: замкнутая кривая (как её делает «Замкнуть кривую» в приложении).</translation>
    </message>
    <message>
        <source>--closed is for --kind composite (the periodic spline is closed by its kind)</source>
        <translation>--closed — для --kind composite (периодический сплайн замкнут по своему виду)</translation>
    </message>
    <message>
        <source>%1: not drawn: %2</source>
        <translation>%1: не нарисовано: %2</translation>
    </message>
    <message>
        <source>Units of a DXF that names none: mm, cm, in or px (default px).</source>
        <translation>Единицы DXF, в котором они не указаны: mm, cm, in или px (по умолчанию px).</translation>
    </message>
    <message>
        <source>--units needs mm, cm, in or px</source>
        <translation>--units требует mm, cm, in или px</translation>
    </message>
    <message>
        <source>DXF output as ASTM D6673 (AAMA) garment pieces: a block per closed curve, its cut line (its seam allowance, if any) and texts on layer 1, sew line 14, notches 4, mirror line 6, the piece&apos;s own grain line 7 (none if it has none), internal lines 8, drill holes 13; polylines unless --dxf spline is given.</source>
        <translation>Вывод DXF как деталей одежды по ASTM D6673 (AAMA): блок на каждую замкнутую кривую, линия реза (припуск на шов, если есть) и тексты на слое 1, линия шва 14, надсечки 4, линия сгиба (зеркальная) 6, собственная линия долевой нити детали 7 (никакой, если её нет), внутренние линии 8, пробивки 13; ломаные, если не задано --dxf spline (сплайны).</translation>
    </message>
    <message>
        <source>%1: the sheet is not flat (its edges are not straight); lay it flat and photograph it again, or give its four corners roughly with --corners x,y;x,y;x,y;x,y</source>
        <translation>%1: лист лежит неровно (его края не прямые); положите его ровно и сфотографируйте снова или укажите примерно четыре его угла с помощью --corners x,y;x,y;x,y;x,y</translation>
    </message>
    <message>
        <source>%1: the rectangle found is about %2 : 1, not %3 (%4 : 1); give the sheet&apos;s size with --sheet, or its four corners roughly with --corners x,y;x,y;x,y;x,y</source>
        <extracomment>%2 and %4 are proportions such as 2.35 and 1.41 (long side : short side), %3 the sheet&apos;s size as given.</extracomment>
        <translation>%1: найденный прямоугольник — примерно %2 : 1, а не %3 (%4 : 1); укажите размер листа с помощью --sheet или примерно четыре его угла с помощью --corners x,y;x,y;x,y;x,y</translation>
    </message>
    <message>
        <source>%1: no reference sheet found (a white rectangle with four straight, clear edges); give its four corners roughly with --corners x,y;x,y;x,y;x,y</source>
        <translation>%1: эталонный лист не найден (белый прямоугольник с четырьмя прямыми чёткими краями); укажите примерно четыре его угла с помощью --corners x,y;x,y;x,y;x,y</translation>
    </message>
    <message>
        <source>%1: no pattern piece found beside the sheet; nothing was written (the sheet was found)</source>
        <translation>%1: рядом с листом не найдена деталь выкройки; ничего не записано (лист найден)</translation>
    </message>
    <message>
        <source>%1: no grain line written for pieces without a grainline: %2</source>
        <translation>%1: для деталей без долевой нити линия долевой нити не записана: %2</translation>
    </message>
</context>
<context>
    <name>kontur::print</name>
    <message>
        <source>Print at 100 % (actual size, not “fit to page”). The grey square must measure 10 cm each way.</source>
        <translation>Печатайте в масштабе 100 % (реальный размер, без «по размеру страницы»). Серый квадрат должен иметь сторону 10 см.</translation>
    </message>
    <message>
        <source>landscape</source>
        <extracomment>Page orientation, inserted after the paper name in the sentence above (A4 landscape).</extracomment>
        <translation>альбомная ориентация</translation>
    </message>
    <message>
        <source>portrait</source>
        <translation>книжная ориентация</translation>
    </message>
    <message>
        <source>Cut each page along the grey line at its left and top, lay it over its neighbours up to their dashed lines, match the circles and tape.</source>
        <translation>Обрежьте каждый лист слева и сверху по серой линии, наложите его на соседние до их пунктирных линий, совместите кружки и склейте.</translation>
    </message>
    <message>
        <source>The drawing is in px: printed at 96 px per inch.</source>
        <translation>Чертёж в пикселях (px): напечатан с разрешением 96 px на дюйм.</translation>
    </message>
    <message>
        <source>10 cm</source>
        <translation>10 см</translation>
    </message>
    <message>
        <source>4 in</source>
        <translation>4 дюйма</translation>
    </message>
    <message>
        <source>Pages after this one: %1 (rows × columns: %2 × %3), %4 %5, overlap %6 mm.</source>
        <extracomment>%1 is the number of pages, %2 × %3 their rows and columns, %4 the paper (A4 or Letter), %5 the orientation (“portrait” or “landscape”, the next messages), %6 a number of millimetres.</extracomment>
        <translation>Листов после этого: %1 (ряды × столбцы: %2 × %3), %4, %5, перекрытие %6 мм.</translation>
    </message>
    <message>
        <source>Place on fold</source>
        <extracomment>Printed along a pattern piece&apos;s fold line: the piece is laid with this edge on the fabric&apos;s fold.</extracomment>
        <translation>Положить на сгиб</translation>
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
            <numerusform>Кроить %n деталь на сгибе</numerusform>
            <numerusform>Кроить %n детали на сгибе</numerusform>
            <numerusform>Кроить %n деталей на сгибе</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Cut %n</source>
        <extracomment>How many pieces to cut, printed on the pattern piece (&quot;Cut 2&quot;).</extracomment>
        <translation>
            <numerusform>Кроить %n деталь</numerusform>
            <numerusform>Кроить %n детали</numerusform>
            <numerusform>Кроить %n деталей</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 in</source>
        <extracomment>A seam&apos;s allowance width printed beside it on the pattern, in inches.</extracomment>
        <translation>%1 дюйма</translation>
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
        <translation>Очистить всё? Все кривые будут удалены.</translation>
    </message>
    <message>
        <source>“%1” is locked: unlock it to change it.</source>
        <translation>«%1» заблокирована: разблокируйте её, чтобы изменить.</translation>
    </message>
    <message>
        <source>Could not read “%1”: %2</source>
        <translation>Не удалось прочитать файл «%1»: %2</translation>
    </message>
    <message numerus="yes">
        <source>%n curve(s) read from “%1”.</source>
        <translation>
            <numerusform>Из файла «%1» прочитана %n кривая.</numerusform>
            <numerusform>Из файла «%1» прочитаны %n кривые.</numerusform>
            <numerusform>Из файла «%1» прочитано %n кривых.</numerusform>
        </translation>
    </message>
    <message>
        <source>Saved “%1”.</source>
        <translation>Файл «%1» сохранён.</translation>
    </message>
    <message>
        <source>This knot lies on the first knot of the closed curve, which joins them already. Nothing was changed.</source>
        <translation>Этот узел совпадает с первым узлом замкнутой кривой, которая уже их соединяет. Ничего не изменено.</translation>
    </message>
    <message>
        <source>This seam allowance follows its curve: change the curve or the allowance&apos;s settings, or detach the allowance to edit it.</source>
        <translation>Этот припуск на шов следует за своей кривой: измените кривую или параметры припуска либо отвяжите припуск, чтобы править его.</translation>
    </message>
    <message>
        <source>No seam allowance of this width fits the curve on that side.</source>
        <translation>Припуск на шов такой ширины не помещается с этой стороны кривой.</translation>
    </message>
    <message>
        <source>This width is more than %1 times the size of the curve: no seam allowance is made of it. Nothing was changed.</source>
        <translation>Эта ширина более чем в %1 раз больше размера кривой: такой припуск на шов не строится. Ничего не изменено.</translation>
    </message>
    <message>
        <source>This seam allowance would need too many pieces at this size. Nothing was changed.</source>
        <translation>Для этого припуска на шов при таком размере понадобилось бы слишком много сегментов. Ничего не изменено.</translation>
    </message>
    <message>
        <source>The seam allowance “%1” keeps the shape it was saved with: its width %2 gives no allowance of its curve.</source>
        <translation>Припуск на шов «%1» сохраняет форму, с которой был сохранён: его ширина %2 не даёт припуска для его кривой.</translation>
    </message>
    <message numerus="yes">
        <source>The autosave setting “%1” cannot be used: a recovery copy is saved every %n second(s).</source>
        <translation>
            <numerusform>Настройку автосохранения «%1» нельзя использовать: копия для восстановления сохраняется каждую %n секунду.</numerusform>
            <numerusform>Настройку автосохранения «%1» нельзя использовать: копия для восстановления сохраняется каждые %n секунды.</numerusform>
            <numerusform>Настройку автосохранения «%1» нельзя использовать: копия для восстановления сохраняется каждые %n секунд.</numerusform>
        </translation>
    </message>
    <message>
        <source>The background image “%1” is missing or cannot be read. The curves are shown without it.</source>
        <translation>Фоновое изображение «%1» отсутствует или не читается. Кривые показаны без него.</translation>
    </message>
    <message>
        <source>The picture “%1” could not be loaded: the file is missing or is not a picture Kontur can read.</source>
        <extracomment>%1 is a file name. The background picture could not be loaded.</extracomment>
        <translation>Не удалось загрузить изображение «%1»: файл отсутствует или это не изображение, которое Kontur может прочитать.</translation>
    </message>
    <message>
        <source>The .txt file is not in the expected format: one “x y” pair per line.</source>
        <translation>Файл .txt имеет неверный формат: нужна одна пара «x y» в строке.</translation>
    </message>
    <message>
        <source>Could not append to “%1”: %2</source>
        <extracomment>%1 is a file name, %2 the reason (from the system). The curve&apos;s points are appended to a .txt file.</extracomment>
        <translation>Не удалось дописать в «%1»: %2</translation>
    </message>
    <message>
        <source>The control points of curves of the kind “%1” cannot be moved: move the knots.</source>
        <extracomment>%1 is the name of a curve kind, as in the kind menu (&quot;Natural spline&quot;, &quot;Composite curve&quot;).</extracomment>
        <translation>Опорные точки кривых вида «%1» перемещать нельзя: перемещайте узлы.</translation>
    </message>
    <message>
        <source>The control points of a composite curve cannot be moved by keyboard: drag them.</source>
        <translation>Опорные точки составной кривой нельзя перемещать с клавиатуры: перетаскивайте их.</translation>
    </message>
    <message>
        <source>Curves of the kind “%1” do not use a parameterization.</source>
        <extracomment>%1 is the name of a curve kind, as in the kind menu (&quot;Bézier curve&quot;, &quot;Natural spline&quot;).</extracomment>
        <translation>Кривые вида «%1» не используют параметризацию.</translation>
    </message>
    <message>
        <source>Too many points: a curve of this kind can have at most %1.</source>
        <extracomment>%1 is the largest number of points a curve of this kind can have (for example 1 000).</extracomment>
        <translation>Слишком много точек: у кривой этого вида их может быть не более %1.</translation>
    </message>
    <message>
        <source>A curve of the kind “%1” needs at least %2 points.</source>
        <extracomment>%1 is the name of a curve kind, as in the kind menu (&quot;Bézier curve&quot;); %2 is a small number (2 to 4).</extracomment>
        <translation>Кривой вида «%1» нужно не менее %2 точек.</translation>
    </message>
    <message>
        <source>Some values are missing or are not numbers: fill in every field with a number.</source>
        <translation>Некоторые значения отсутствуют или не являются числами: заполните каждое поле числом.</translation>
    </message>
    <message>
        <source>The knots of this curve (kind “%1”) do not define a curve: they need at least 4 different positions.</source>
        <extracomment>%1 is the name of a curve kind, as in the kind menu (&quot;Least-squares cubic&quot;).</extracomment>
        <translation>Узлы этой кривой (вид «%1») не задают кривую: нужны хотя бы 4 различных положения.</translation>
    </message>
    <message>
        <source>Too large: the coordinates would exceed the largest number Kontur can hold (about %1). Nothing was changed.</source>
        <translation>Слишком большое значение: координаты превысили бы наибольшее число, которое может хранить Kontur (около %1). Ничего не изменено.</translation>
    </message>
    <message>
        <source>This is not possible for curves of the kind “%1”.</source>
        <extracomment>%1 is the name of a curve kind, as in the kind menu (&quot;Bézier curve&quot;, &quot;Global B-spline&quot;).</extracomment>
        <translation>Для кривых вида «%1» это невозможно.</translation>
    </message>
    <message>
        <source>A seam allowance is still being computed: wait for it or cancel it first.</source>
        <translation>Припуск на шов ещё вычисляется: дождитесь его или сначала отмените.</translation>
    </message>
    <message>
        <source>The seam allowance was cancelled. Nothing was changed.</source>
        <translation>Припуск на шов отменён. Ничего не изменено.</translation>
    </message>
    <message>
        <source>The curve changed while its seam allowance was computed. Nothing was changed; add or apply it again.</source>
        <translation>Кривая изменилась, пока вычислялся её припуск на шов. Ничего не изменено; добавьте или примените его снова.</translation>
    </message>
    <message numerus="yes">
        <source>%n text(s)</source>
        <translation>
            <numerusform>%n текст</numerusform>
            <numerusform>%n текста</numerusform>
            <numerusform>%n текстов</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n dimension(s)</source>
        <translation>
            <numerusform>%n размер</numerusform>
            <numerusform>%n размера</numerusform>
            <numerusform>%n размеров</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n 3D object(s)</source>
        <translation>
            <numerusform>%n 3D-объект</numerusform>
            <numerusform>%n 3D-объекта</numerusform>
            <numerusform>%n 3D-объектов</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n image(s)</source>
        <translation>
            <numerusform>%n изображение</numerusform>
            <numerusform>%n изображения</numerusform>
            <numerusform>%n изображений</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n spline(s) given only by fit points or weights</source>
        <translation>
            <numerusform>%n сплайн, заданный только точками аппроксимации или весами</numerusform>
            <numerusform>%n сплайна, заданных только точками аппроксимации или весами</numerusform>
            <numerusform>%n сплайнов, заданных только точками аппроксимации или весами</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n other object(s)</source>
        <translation>
            <numerusform>%n другой объект</numerusform>
            <numerusform>%n других объекта</numerusform>
            <numerusform>%n других объектов</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n curve(s) read from “%1”; not drawn: %2.</source>
        <translation>
            <numerusform>Из «%1» прочитана %n кривая; не нарисовано: %2.</numerusform>
            <numerusform>Из «%1» прочитаны %n кривые; не нарисовано: %2.</numerusform>
            <numerusform>Из «%1» прочитано %n кривых; не нарисовано: %2.</numerusform>
        </translation>
    </message>
    <message>
        <source>Could not write “%1”: %2 The file was left as it was.</source>
        <translation>Не удалось записать файл «%1»: %2 Файл остался без изменений.</translation>
    </message>
    <message numerus="yes">
        <source>%n curve(s) read from “%1”, which does not say its units: read in %2, as chosen for such files.</source>
        <extracomment>%1 is a file name, %2 a unit (mm, cm, in or px) the user chose once for DXF files without units.</extracomment>
        <translation>
            <numerusform>Из «%1», где не указаны единицы, прочитана %n кривая: в единицах %2, как выбрано для таких файлов.</numerusform>
            <numerusform>Из «%1», где не указаны единицы, прочитаны %n кривые: в единицах %2, как выбрано для таких файлов.</numerusform>
            <numerusform>Из «%1», где не указаны единицы, прочитано %n кривых: в единицах %2, как выбрано для таких файлов.</numerusform>
        </translation>
    </message>
    <message>
        <source>Not drawn: %1.</source>
        <extracomment>Appended to the message that curves were read from a file; %1 lists what was not drawn.</extracomment>
        <translation>Не нарисовано: %1.</translation>
    </message>
    <message>
        <source>DXF files that do not say their units are read in %1 from the next import on.</source>
        <extracomment>%1 is a unit (mm, cm, in or px).</extracomment>
        <translation>Файлы DXF без указанных единиц со следующего импорта читаются в единицах %1.</translation>
    </message>
    <message>
        <source>Nothing was exported: pattern software takes each piece as a closed curve, and this document has no visible closed curve. Close the outline of each piece first.</source>
        <extracomment>AAMA (ASTM D6673) is the DXF that garment pattern software reads; a piece is a garment pattern piece.</extracomment>
        <translation>Ничего не экспортировано: программы работы с выкройками принимают каждую деталь как замкнутую кривую, а в этом документе нет видимой замкнутой кривой. Сначала замкните контур каждой детали.</translation>
    </message>
    <message>
        <source>Seam allowance of %2 added to “%1”. To change it, select it and choose Seam allowance again.</source>
        <extracomment>%1 is the curve&apos;s name, %2 the width with its unit (10.00 mm).</extracomment>
        <translation>К кривой «%1» добавлен припуск на шов %2. Чтобы изменить его, выделите припуск и снова выберите «Припуск на шов».</translation>
    </message>
    <message numerus="yes">
        <source>“%1” traced with %n knot(s). For the next piece, choose Trace outline again.</source>
        <extracomment>%1 is the new curve&apos;s name; Trace outline is the command in the Trace menu.</extracomment>
        <translation>
            <numerusform>Кривая «%1» обведена: %n узел. Для следующей детали снова выберите «Обвести контур».</numerusform>
            <numerusform>Кривая «%1» обведена: %n узла. Для следующей детали снова выберите «Обвести контур».</numerusform>
            <numerusform>Кривая «%1» обведена: %n узлов. Для следующей детали снова выберите «Обвести контур».</numerusform>
        </translation>
    </message>
    <message>
        <source>the grainline</source>
        <extracomment>One of the marks found on a traced pattern piece, listed after the curve&apos;s name.</extracomment>
        <translation>долевая нить</translation>
    </message>
    <message>
        <source>the fold line</source>
        <extracomment>One of the marks found on a traced pattern piece: the edge laid on the fabric&apos;s fold.</extracomment>
        <translation>линия сгиба</translation>
    </message>
    <message numerus="yes">
        <source>%n notch(es)</source>
        <extracomment>One of the marks found on a traced pattern piece (V or slit cuts in its edge).</extracomment>
        <translation>
            <numerusform>%n надсечка</numerusform>
            <numerusform>%n надсечки</numerusform>
            <numerusform>%n надсечек</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n drill hole(s)</source>
        <extracomment>One of the marks found on a traced pattern piece.</extracomment>
        <translation>
            <numerusform>%n пробивка</numerusform>
            <numerusform>%n пробивки</numerusform>
            <numerusform>%n пробивок</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>“%1” traced with %n knot(s) as a pattern piece with %2. Check them under Pattern piece; for the next piece, choose Trace outline again.</source>
        <extracomment>%1 is the new curve&apos;s name, %2 the marks found on it (&quot;the grainline, 3 notches, 1 drill hole&quot;); Pattern piece is the command that opens the piece bar; Trace outline the command in the Trace menu.</extracomment>
        <translation>
            <numerusform>Кривая «%1» обведена как деталь выкройки: %n узел; найденные метки: %2. Проверьте их в «Деталь выкройки»; для следующей детали снова выберите «Обвести контур».</numerusform>
            <numerusform>Кривая «%1» обведена как деталь выкройки: %n узла; найденные метки: %2. Проверьте их в «Деталь выкройки»; для следующей детали снова выберите «Обвести контур».</numerusform>
            <numerusform>Кривая «%1» обведена как деталь выкройки: %n узлов; найденные метки: %2. Проверьте их в «Деталь выкройки»; для следующей детали снова выберите «Обвести контур».</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>“%1” was written, but %n piece(s) without a grainline have no grain line in it: %2. Marker making cannot lay them on grain; draw each piece&apos;s grainline.</source>
        <extracomment>%1 is the file, %2 the pieces&apos; names; the grainline is the pattern piece&apos;s straight-of-grain line.</extracomment>
        <translation>
            <numerusform>«%1» записан, но у %n детали без долевой нити в нём нет линии долевой нити: %2. При раскладке её нельзя положить по долевой; проведите долевую нить на каждой детали.</numerusform>
            <numerusform>«%1» записан, но у %n деталей без долевой нити в нём нет линии долевой нити: %2. При раскладке их нельзя положить по долевой; проведите долевую нить на каждой детали.</numerusform>
            <numerusform>«%1» записан, но у %n деталей без долевой нити в нём нет линии долевой нити: %2. При раскладке их нельзя положить по долевой; проведите долевую нить на каждой детали.</numerusform>
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
        <translation>%1 дюйма</translation>
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
        <translation>дюймы</translation>
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
