<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ru">
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
        <source>Points</source>
        <translation>Точки</translation>
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
        <source>Opening documents is not available in this version yet: %1</source>
        <translation>Открытие документов в этой версии пока недоступно: %1</translation>
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
</context>
</TS>
