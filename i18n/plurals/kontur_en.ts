<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
<context>
    <name>BasisPlot</name>
    <message numerus="yes">
        <source>Too many basis functions to draw (%n).</source>
        <translation>
            <numerusform>Too many basis functions to draw (%n).</numerusform>
            <numerusform>Too many basis functions to draw (%n).</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Hermite basis functions on the curve&apos;s %n segment(s)</source>
        <translation>
            <numerusform>Hermite basis functions on the curve&apos;s %n segment</numerusform>
            <numerusform>Hermite basis functions on the curve&apos;s %n segments</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>PrintDialog</name>
    <message numerus="yes">
        <source>%n page(s) to tape together: %1 × %2 (rows × columns), %3.</source>
        <translation>
            <numerusform>%n page to tape together: %1 × %2 (rows × columns), %3.</numerusform>
            <numerusform>%n pages to tape together: %1 × %2 (rows × columns), %3.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SidePanel</name>
    <message numerus="yes">
        <source>%1 · %n point(s) · length %2</source>
        <extracomment>%1 is the curve&apos;s kind, %2 its length with its unit (12.5 mm).</extracomment>
        <translation>
            <numerusform>%1 · %n point · length %2</numerusform>
            <numerusform>%1 · %n points · length %2</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>TeachingBar</name>
    <message numerus="yes">
        <source>degree %1 → %2 (%n point(s))</source>
        <translation>
            <numerusform>degree %1 → %2 (%n point)</numerusform>
            <numerusform>degree %1 → %2 (%n points)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>TraceBar</name>
    <message numerus="yes">
        <source>last stroke: %n segment(s)</source>
        <translation>
            <numerusform>last stroke: %n segment</numerusform>
            <numerusform>last stroke: %n segments</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>kontur::FunctionSplinePlot</name>
    <message numerus="yes">
        <source>Knots: give %n number(s), four more than the number of values.</source>
        <translation>
            <numerusform>Knots: give %n number, four more than the number of values.</numerusform>
            <numerusform>Knots: give %n numbers, four more than the number of values.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Knots: give %n number(s), one per function value.</source>
        <translation>
            <numerusform>Knots: give %n number, one per function value.</numerusform>
            <numerusform>Knots: give %n numbers, one per function value.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Derivatives: give %n number(s), one per knot.</source>
        <translation>
            <numerusform>Derivatives: give %n number, one per knot.</numerusform>
            <numerusform>Derivatives: give %n numbers, one per knot.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The polynomial is drawn for at most %n point(s).</source>
        <translation>
            <numerusform>The polynomial is drawn for at most %n point.</numerusform>
            <numerusform>The polynomial is drawn for at most %n points.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>kontur::cli</name>
    <message numerus="yes">
        <source>expected %n file name(s), got %1</source>
        <translation>
            <numerusform>expected %n file name, got %1</numerusform>
            <numerusform>expected %n file names, got %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>kontur::print</name>
    <message numerus="yes">
        <source>Cut %n on fold</source>
        <extracomment>How many pieces to cut, printed on the pattern piece; the piece lies on the fabric&apos;s fold.</extracomment>
        <translation>
            <numerusform>Cut %n on fold</numerusform>
            <numerusform>Cut %n on fold</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Cut %n</source>
        <extracomment>How many pieces to cut, printed on the pattern piece (&quot;Cut 2&quot;).</extracomment>
        <translation>
            <numerusform>Cut %n</numerusform>
            <numerusform>Cut %n</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>messages</name>
    <message numerus="yes">
        <source>%n curve(s) read from “%1”.</source>
        <translation>
            <numerusform>%n curve read from “%1”.</numerusform>
            <numerusform>%n curves read from “%1”.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The autosave setting “%1” cannot be used: a recovery copy is saved every %n second(s).</source>
        <translation>
            <numerusform>The autosave setting “%1” cannot be used: a recovery copy is saved every second.</numerusform>
            <numerusform>The autosave setting “%1” cannot be used: a recovery copy is saved every %n seconds.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n text(s)</source>
        <translation>
            <numerusform>%n text</numerusform>
            <numerusform>%n texts</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n dimension(s)</source>
        <translation>
            <numerusform>%n dimension</numerusform>
            <numerusform>%n dimensions</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n 3D object(s)</source>
        <translation>
            <numerusform>%n 3D object</numerusform>
            <numerusform>%n 3D objects</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n image(s)</source>
        <translation>
            <numerusform>%n image</numerusform>
            <numerusform>%n images</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n spline(s) given only by fit points or weights</source>
        <translation>
            <numerusform>%n spline given only by fit points or weights</numerusform>
            <numerusform>%n splines given only by fit points or weights</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n other object(s)</source>
        <translation>
            <numerusform>%n other object</numerusform>
            <numerusform>%n other objects</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n curve(s) read from “%1”; not drawn: %2.</source>
        <translation>
            <numerusform>%n curve read from “%1”; not drawn: %2.</numerusform>
            <numerusform>%n curves read from “%1”; not drawn: %2.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n curve(s) read from “%1”, which does not say its units: read in %2, as chosen for such files.</source>
        <extracomment>%1 is a file name, %2 a unit (mm, cm, in or px) the user chose once for DXF files without units.</extracomment>
        <translation>
            <numerusform>%n curve read from “%1”, which does not say its units: read in %2, as chosen for such files.</numerusform>
            <numerusform>%n curves read from “%1”, which does not say its units: read in %2, as chosen for such files.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>“%1” traced with %n knot(s). For the next piece, choose Trace outline again.</source>
        <extracomment>%1 is the new curve&apos;s name; Trace outline is the command in the Trace menu.</extracomment>
        <translation>
            <numerusform>“%1” traced with %n knot. For the next piece, choose Trace outline again.</numerusform>
            <numerusform>“%1” traced with %n knots. For the next piece, choose Trace outline again.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n notch(es)</source>
        <extracomment>One of the marks found on a traced pattern piece (V or slit cuts in its edge).</extracomment>
        <translation>
            <numerusform>%n notch</numerusform>
            <numerusform>%n notches</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n drill hole(s)</source>
        <extracomment>One of the marks found on a traced pattern piece.</extracomment>
        <translation>
            <numerusform>%n drill hole</numerusform>
            <numerusform>%n drill holes</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>“%1” traced with %n knot(s) as a pattern piece with %2. Check them under Pattern piece; for the next piece, choose Trace outline again.</source>
        <extracomment>%1 is the new curve&apos;s name, %2 the marks found on it (&quot;the grainline, 3 notches, 1 drill hole&quot;); Pattern piece is the command that opens the piece bar; Trace outline the command in the Trace menu.</extracomment>
        <translation>
            <numerusform>“%1” traced with %n knot as a pattern piece with %2. Check them under Pattern piece; for the next piece, choose Trace outline again.</numerusform>
            <numerusform>“%1” traced with %n knots as a pattern piece with %2. Check them under Pattern piece; for the next piece, choose Trace outline again.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>“%1” was written, but %n piece(s) without a grainline have no grain line in it: %2. Marker making cannot lay them on grain; draw each piece&apos;s grainline.</source>
        <extracomment>%1 is the file, %2 the pieces&apos; names; the grainline is the pattern piece&apos;s straight-of-grain line.</extracomment>
        <translation>
            <numerusform>“%1” was written, but %n piece without a grainline has no grain line in it: %2. Marker making cannot lay it on grain; draw each piece&apos;s grainline.</numerusform>
            <numerusform>“%1” was written, but %n pieces without a grainline have no grain line in it: %2. Marker making cannot lay them on grain; draw each piece&apos;s grainline.</numerusform>
        </translation>
    </message>
</context>
</TS>
