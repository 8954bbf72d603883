<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="bg">
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
        <source>New Bézier curve: tap or click control point %1 of %2. Esc cancels.</source>
        <translation>Нова крива на Безие: докоснете или щракнете, за да поставите контролна точка %1 от %2. Esc отказва.</translation>
    </message>
    <message>
        <source>Press “New Bézier” and tap 4 points to draw your first curve.</source>
        <translation>Натиснете „Нова крива на Безие“ и докоснете 4 точки, за да начертаете първата си крива.</translation>
    </message>
    <message>
        <source>Drag a point to move it. Drag the canvas to pan; pinch or scroll to zoom.</source>
        <translation>Влачете точка, за да я преместите. Влачете платното, за да местите изгледа; мащабирайте с два пръста или с колелцето.</translation>
    </message>
</context>
<context>
    <name>SidePanel</name>
    <message>
        <source>Curves</source>
        <translation>Криви</translation>
    </message>
    <message numerus="yes">
        <source>%1 · %2 · %n point(s)</source>
        <translation>
            <numerusform>%1 · %2 · %n точка</numerusform>
            <numerusform>%1 · %2 · %n точки</numerusform>
        </translation>
    </message>
    <message>
        <source>No curves yet.</source>
        <translation>Все още няма криви.</translation>
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
        <source>Opening documents is not available in this version yet: %1</source>
        <translation>Отварянето на документи още не е налично в тази версия: %1</translation>
    </message>
</context>
</TS>
