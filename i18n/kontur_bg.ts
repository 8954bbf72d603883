<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="bg">
<context>
    <name>CanvasView</name>
    <message>
        <source>grid %1</source>
        <translation>мрежа %1</translation>
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
        <translation>Възстановяване</translation>
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
    <name>Main</name>
    <message>
        <source>Kontur</source>
        <translation>Kontur</translation>
    </message>
    <message>
        <source>New Bézier</source>
        <translation>Нова крива на Безие</translation>
    </message>
    <message>
        <source>Place 4 control points to make a cubic Bézier curve (B)</source>
        <translation>Поставете 4 контролни точки, за да създадете кубична крива на Безие (B)</translation>
    </message>
    <message>
        <source>Move points</source>
        <translation>Преместване на точки</translation>
    </message>
    <message>
        <source>Drag points to change curves; drag the canvas to pan (Esc)</source>
        <translation>Влачете точките, за да променяте кривите; влачете платното, за да местите изгледа (Esc)</translation>
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
        <source>Zoom out</source>
        <translation>Намали</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
    <message>
        <source>Zoom in</source>
        <translation>Увеличи</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>Побиране</translation>
    </message>
    <message>
        <source>Show all curves (F)</source>
        <translation>Покажи всички криви (F)</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Език</translation>
    </message>
    <message>
        <source>Panel</source>
        <translation>Панел</translation>
    </message>
    <message>
        <source>Press “New Bézier” and tap 4 points to draw your first curve.</source>
        <translation>Натиснете „Нова крива на Безие“ и докоснете 4 точки, за да начертаете първата си крива.</translation>
    </message>
    <message>
        <source>Drag a point to move it. Drag the canvas to pan; pinch or scroll to zoom.</source>
        <translation>Влачете точка, за да я преместите. Влачете платното, за да местите изгледа; мащабирайте с два пръста или с колелцето.</translation>
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
        <translation>Готово</translation>
    </message>
    <message>
        <source>Finish the curve with the points placed so far (Enter)</source>
        <translation>Завършете кривата с поставените досега точки (Enter)</translation>
    </message>
    <message>
        <source>Constrained</source>
        <translation>Ограничено</translation>
    </message>
    <message>
        <source>Composite handles keep their direction and change only their length (or drag with the right button or Shift)</source>
        <translation>Манипулаторите на съставната крива запазват посоката си и променят само дължината си (или влачете с десния бутон или Shift)</translation>
    </message>
    <message>
        <source>New curve: tap or click its points (%1 placed). Press Done to finish, Esc to cancel.</source>
        <translation>Нова крива: докоснете или щракнете точките ѝ (поставени: %1). Натиснете „Готово“ за край, Esc за отказ.</translation>
    </message>
    <message>
        <source>New curve: tap or click point %1 of %2. Esc cancels.</source>
        <translation>Нова крива: докоснете или щракнете, за да поставите точка %1 от %2. Esc отказва.</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Файл</translation>
    </message>
    <message>
        <source>New</source>
        <translation>Нов</translation>
    </message>
    <message>
        <source>Open…</source>
        <translation>Отваряне…</translation>
    </message>
    <message>
        <source>Open recent</source>
        <translation>Скорошни файлове</translation>
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
        <source>Import points, CSV or SVG…</source>
        <translation>Импортиране на точки, CSV или SVG…</translation>
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
        <source>Grid</source>
        <translation>Мрежа</translation>
    </message>
    <message>
        <source>Show or hide the grid and the axes (G)</source>
        <translation>Покажи или скрий мрежата и осите (G)</translation>
    </message>
    <message>
        <source>Reset all</source>
        <translation>Изчистване на всичко</translation>
    </message>
    <message>
        <source>Close message</source>
        <translation>Затваряне на съобщението</translation>
    </message>
    <message>
        <source>Kontur documents (*.kontur)</source>
        <translation>Документи на Kontur (*.kontur)</translation>
    </message>
    <message>
        <source>Points, CSV and SVG files (*.txt *.csv *.svg)</source>
        <translation>Файлове с точки, CSV и SVG (*.txt *.csv *.svg)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Всички файлове (*)</translation>
    </message>
    <message>
        <source>Open</source>
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
        <source>Points, CSV, SVG and Kontur files (*.txt *.csv *.svg *.kontur)</source>
        <translation>Файлове с точки, CSV, SVG и Kontur (*.txt *.csv *.svg *.kontur)</translation>
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
        <source>Unsaved changes</source>
        <translation>Незапазени промени</translation>
    </message>
    <message>
        <source>“%1” has changes that are not saved. Save them first?</source>
        <translation>Документът „%1“ има незапазени промени. Да се запазят ли първо?</translation>
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
        <source>Load background image</source>
        <translation>Зареждане на фоново изображение</translation>
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
        <translation>Ред на сплайна</translation>
    </message>
    <message>
        <source>Node type</source>
        <translation>Вид на възела</translation>
    </message>
    <message>
        <source>Smooth</source>
        <translation>Гладък</translation>
    </message>
    <message>
        <source>Symmetric</source>
        <translation>Симетричен</translation>
    </message>
    <message>
        <source>Corner</source>
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
        <translation>Информация</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Дължина</translation>
    </message>
    <message>
        <source>Fit error (RMS / max)</source>
        <translation>Грешка на апроксимацията (RMS / макс.)</translation>
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
        <source>kontur: unknown language &quot;%1&quot;; choose one of %2.</source>
        <translation>kontur: непознат език „%1“; изберете един от: %2.</translation>
    </message>
    <message>
        <source>kontur: give at most one file to open.</source>
        <translation>kontur: посочете най-много един файл за отваряне.</translation>
    </message>
    <message>
        <source>kontur: cannot open &quot;%1&quot;: no such file.</source>
        <translation>kontur: не може да се отвори „%1“: няма такъв файл.</translation>
    </message>
</context>
<context>
    <name>kontur</name>
    <message>
        <source>Add %1</source>
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
        <translation>Безие %1</translation>
    </message>
    <message>
        <source>Delete %1</source>
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
        <translation>През 4 точки %1</translation>
    </message>
    <message>
        <source>Least squares %1</source>
        <translation>Най-малки квадрати %1</translation>
    </message>
    <message>
        <source>Composite %1</source>
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
        <translation>Закрепен сплайн</translation>
    </message>
    <message>
        <source>Not-a-knot spline</source>
        <translation>Сплайн с условие not-a-knot</translation>
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
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>Change order</source>
        <translation>Промяна на реда на сплайна</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Без име</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>Импортиране на %1</translation>
    </message>
</context>
<context>
    <name>messages</name>
    <message>
        <source>File upload error!</source>
        <translation>Грешка при зареждане на файла!</translation>
    </message>
    <message>
        <source>The .txt file was not correct!</source>
        <translation>Файлът .txt не е правилен!</translation>
    </message>
    <message>
        <source>Output error!</source>
        <translation>Грешка при извеждане!</translation>
    </message>
    <message>
        <source>Do you want to reset everything? All curves will be removed.</source>
        <translation>Искате ли да изчистите всичко? Всички криви ще бъдат премахнати.</translation>
    </message>
    <message>
        <source>Not allowed to move control points of a %1: move its knots.</source>
        <translation>Контролните точки на крива от вида „%1“ не могат да се местят: местете възлите ѝ.</translation>
    </message>
    <message>
        <source>Not allowed to move control points of a composite curve by keyboard!</source>
        <translation>Контролните точки на съставна крива не могат да се местят от клавиатурата!</translation>
    </message>
    <message>
        <source>A %1 does not use a parameterization.</source>
        <translation>Крива от вида „%1“ не използва параметризация.</translation>
    </message>
    <message>
        <source>The maximum count of points is %1!</source>
        <translation>Максималният брой точки е %1!</translation>
    </message>
    <message>
        <source>A %1 can not have less than %2 points!</source>
        <translation>Крива от вида „%1“ не може да има по-малко от %2 точки!</translation>
    </message>
    <message>
        <source>Must fill all values with numbers!</source>
        <translation>Всички стойности трябва да са попълнени с числа!</translation>
    </message>
    <message>
        <source>“%1” is locked: unlock it to change it.</source>
        <translation>„%1“ е заключена: отключете я, за да я промените.</translation>
    </message>
    <message>
        <source>The knots of this %1 do not define a curve: they need at least 4 different positions.</source>
        <translation>Възлите на тази крива от вида „%1“ не определят крива: нужни са поне 4 различни положения.</translation>
    </message>
    <message>
        <source>This is not possible for a %1.</source>
        <translation>Това не е възможно за крива от вида „%1“.</translation>
    </message>
    <message>
        <source>Could not read “%1”: %2</source>
        <translation>Файлът „%1“ не може да бъде прочетен: %2</translation>
    </message>
    <message>
        <source>Could not write “%1”: %2. The file was left as it was.</source>
        <translation>Файлът „%1“ не може да бъде записан: %2. Файлът е оставен непроменен.</translation>
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
</context>
</TS>
