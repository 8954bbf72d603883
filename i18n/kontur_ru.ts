<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ru">
<context>
    <name>CanvasView</name>
    <message>
        <source>grid %1</source>
        <translation>сетка %1</translation>
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
    <name>Main</name>
    <message>
        <source>Kontur</source>
        <translation>Kontur</translation>
    </message>
    <message>
        <source>New Bézier</source>
        <translation>Новая кривая Безье</translation>
    </message>
    <message>
        <source>Place 4 control points to make a cubic Bézier curve (B)</source>
        <translation>Поставьте 4 опорные точки, чтобы построить кубическую кривую Безье (B)</translation>
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
        <source>Undo</source>
        <translation>Отменить</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Повторить</translation>
    </message>
    <message>
        <source>Zoom out</source>
        <translation>Уменьшить</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>Zoom in</source>
        <translation>Увеличить</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Вписать</translation>
    </message>
    <message>
        <source>Show all curves (F)</source>
        <translation>Показать все кривые (F)</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Язык</translation>
    </message>
    <message>
        <source>Panel</source>
        <translation>Панель</translation>
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
        <source>New curve</source>
        <translation>Новая кривая</translation>
    </message>
    <message>
        <source>Choose the kind of curve to place</source>
        <translation>Выберите вид кривой для построения</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>Готово</translation>
    </message>
    <message>
        <source>Finish the curve with the points placed so far (Enter)</source>
        <translation>Завершить кривую по уже поставленным точкам (Enter)</translation>
    </message>
    <message>
        <source>Constrained</source>
        <translation>С ограничением</translation>
    </message>
    <message>
        <source>Composite handles keep their direction and change only their length (or drag with the right button or Shift)</source>
        <translation>Направляющие точки составной кривой сохраняют направление и меняют только длину (или перетаскивайте правой кнопкой либо с Shift)</translation>
    </message>
    <message>
        <source>New curve: tap or click its points (%1 placed). Press Done to finish, Esc to cancel.</source>
        <translation>Новая кривая: касайтесь или щёлкайте, чтобы ставить её точки (поставлено: %1). «Готово» — завершить, Esc — отмена.</translation>
    </message>
    <message>
        <source>New curve: tap or click point %1 of %2. Esc cancels.</source>
        <translation>Новая кривая: коснитесь или щёлкните, чтобы поставить точку %1 из %2. Esc — отмена.</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Файл</translation>
    </message>
    <message>
        <source>New</source>
        <translation>Создать</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Открыть…</translation>
    </message>
    <message>
        <source>Open recent</source>
        <translation>Открыть недавние</translation>
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
        <source>Import points, CSV or SVG…</source>
        <translation>Импортировать точки, CSV или SVG…</translation>
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
        <source>Export PNG (view size)…</source>
        <translation>Экспортировать в PNG (размер вида)…</translation>
    </message>
    <message>
        <source>Export PNG (2× view size)…</source>
        <translation>Экспортировать в PNG (2× размер вида)…</translation>
    </message>
    <message>
        <source>Export PNG (4× view size)…</source>
        <translation>Экспортировать в PNG (4× размер вида)…</translation>
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
        <source>Grid</source>
        <translation>Сетка</translation>
    </message>
    <message>
        <source>Show or hide the grid and the axes (G)</source>
        <translation>Показать или скрыть сетку и оси (G)</translation>
    </message>
    <message>
        <source>Reset all</source>
        <translation>Сбросить всё</translation>
    </message>
    <message>
        <source>Close message</source>
        <translation>Закрыть сообщение</translation>
    </message>
    <message>
        <source>Kontur documents (*.kontur)</source>
        <translation>Документы Kontur (*.kontur)</translation>
    </message>
    <message>
        <source>Points, CSV and SVG files (*.txt *.csv *.svg)</source>
        <translation>Файлы точек, CSV и SVG (*.txt *.csv *.svg)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Все файлы (*)</translation>
    </message>
    <message>
        <source>Open</source>
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
        <source>Points, CSV, SVG and Kontur files (*.txt *.csv *.svg *.kontur)</source>
        <translation>Файлы точек, CSV, SVG и Kontur (*.txt *.csv *.svg *.kontur)</translation>
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
        <source>Unsaved changes</source>
        <translation>Несохранённые изменения</translation>
    </message>
    <message>
        <source>“%1” has changes that are not saved. Save them first?</source>
        <translation>В документе «%1» есть несохранённые изменения. Сначала сохранить их?</translation>
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
        <source>Load background image</source>
        <translation>Загрузить фоновое изображение</translation>
    </message>
    <message>
        <source>Images (*.png *.jpg *.jpeg *.bmp *.gif *.webp)</source>
        <translation>Изображения (*.png *.jpg *.jpeg *.bmp *.gif *.webp)</translation>
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
        <translation>Порядок</translation>
    </message>
    <message>
        <source>Node type</source>
        <translation>Тип узла</translation>
    </message>
    <message>
        <source>Smooth</source>
        <translation>Гладкий</translation>
    </message>
    <message>
        <source>Symmetric</source>
        <translation>Симметричный</translation>
    </message>
    <message>
        <source>Corner</source>
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
        <source>kontur: unknown language &quot;%1&quot;; choose one of %2.</source>
        <translation>kontur: неизвестный язык «%1»; выберите один из: %2.</translation>
    </message>
    <message>
        <source>kontur: give at most one file to open.</source>
        <translation>kontur: укажите не более одного файла для открытия.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: no such file.</source>
        <translation>kontur: не удаётся открыть «%1»: файл не найден.</translation>
    </message>
</context>
<context>
    <name>kontur</name>
    <message>
        <source>Add %1</source>
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
        <translation>Безье %1</translation>
    </message>
    <message>
        <source>Delete %1</source>
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
        <translation>Через 4 точки %1</translation>
    </message>
    <message>
        <source>Least squares %1</source>
        <translation>МНК %1</translation>
    </message>
    <message>
        <source>Composite %1</source>
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
        <translation>Сбросить всё</translation>
    </message>
    <message>
        <source>Natural spline</source>
        <translation>Естественный сплайн</translation>
    </message>
    <message>
        <source>Clamped spline</source>
        <translation>Сплайн с заданными производными на концах</translation>
    </message>
    <message>
        <source>Not-a-knot spline</source>
        <translation>Сплайн с условием not-a-knot</translation>
    </message>
    <message>
        <source>Periodic spline</source>
        <translation>Периодический сплайн</translation>
    </message>
    <message>
        <source>Catmull–Rom spline</source>
        <translation>Сплайн Кэтмелла–Рома</translation>
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
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>Change order</source>
        <translation>Изменить порядок сплайна</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Без имени</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Импортировать %1</translation>
    </message>
</context>
<context>
    <name>messages</name>
    <message>
        <source>File upload error!</source>
        <translation>Ошибка загрузки файла!</translation>
    </message>
    <message>
        <source>The .txt file was not correct!</source>
        <translation>Файл .txt некорректен!</translation>
    </message>
    <message>
        <source>Output error!</source>
        <translation>Ошибка вывода!</translation>
    </message>
    <message>
        <source>Do you want to reset everything? All curves will be removed.</source>
        <translation>Сбросить всё? Все кривые будут удалены.</translation>
    </message>
    <message>
        <source>Not allowed to move control points of a %1: move its knots.</source>
        <translation>Опорные точки кривой типа «%1» перемещать нельзя: перемещайте её узлы.</translation>
    </message>
    <message>
        <source>Not allowed to move control points of a composite curve by keyboard!</source>
        <translation>Опорные точки составной кривой нельзя перемещать с клавиатуры!</translation>
    </message>
    <message>
        <source>A %1 does not use a parameterization.</source>
        <translation>Кривая типа «%1» не использует параметризацию.</translation>
    </message>
    <message>
        <source>The maximum count of points is %1!</source>
        <translation>Максимальное число точек — %1!</translation>
    </message>
    <message>
        <source>A %1 can not have less than %2 points!</source>
        <translation>У кривой типа «%1» не может быть меньше %2 точек!</translation>
    </message>
    <message>
        <source>Must fill all values with numbers!</source>
        <translation>Все значения должны быть заполнены числами!</translation>
    </message>
    <message>
        <source>“%1” is locked: unlock it to change it.</source>
        <translation>«%1» заблокирована: разблокируйте её, чтобы изменить.</translation>
    </message>
    <message>
        <source>The knots of this %1 do not define a curve: they need at least 4 different positions.</source>
        <translation>Узлы этой кривой типа «%1» не задают кривую: нужно не менее 4 различных положений.</translation>
    </message>
    <message>
        <source>This is not possible for a %1.</source>
        <translation>Для кривой типа «%1» это невозможно.</translation>
    </message>
    <message>
        <source>Could not read “%1”: %2</source>
        <translation>Не удалось прочитать файл «%1»: %2</translation>
    </message>
    <message>
        <source>Could not write “%1”: %2. The file was left as it was.</source>
        <translation>Не удалось записать файл «%1»: %2. Файл остался без изменений.</translation>
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
</context>
</TS>
