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
        <source>New Bézier curve: tap or click control point %1 of %2. Esc cancels.</source>
        <translation>Новая кривая Безье: коснитесь или щёлкните, чтобы поставить опорную точку %1 из %2. Esc — отмена.</translation>
    </message>
    <message>
        <source>Press “New Bézier” and tap 4 points to draw your first curve.</source>
        <translation>Нажмите «Новая кривая Безье» и поставьте 4 точки, чтобы построить первую кривую.</translation>
    </message>
    <message>
        <source>Drag a point to move it. Drag the canvas to pan; pinch or scroll to zoom.</source>
        <translation>Перетащите точку, чтобы переместить её. Перетаскивайте холст, чтобы сдвигать вид; масштабируйте двумя пальцами или колёсиком.</translation>
    </message>
</context>
<context>
    <name>SidePanel</name>
    <message>
        <source>Curves</source>
        <translation>Кривые</translation>
    </message>
    <message numerus="yes">
        <source>%1 · %2 · %n point(s)</source>
        <translation>
            <numerusform>%1 · %2 · %n точка</numerusform>
            <numerusform>%1 · %2 · %n точки</numerusform>
            <numerusform>%1 · %2 · %n точек</numerusform>
        </translation>
    </message>
    <message>
        <source>No curves yet.</source>
        <translation>Кривых пока нет.</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Точки</translation>
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
</context>
</TS>
