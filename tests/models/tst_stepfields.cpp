// The teaching views without a keyboard: one number of a typed list changed by − and + (the step is a
// unit of its last shown decimal, every other character stays as typed, in the languages with a
// decimal comma too), the function-spline view's fields stepped as one undo step each, and KG-202's
// segment example one tap away with the numbers its formulas give.
#include "models/teaching/functionspline.h"
#include "models/teaching/practicumplot.h"
#include "text/numbertext.h"

#include <QtTest>

#include <algorithm>
#include <cmath>

using kontur::FunctionSplinePlot;
using kontur::PracticumPlot;

class TestStepFields final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void init() { QLocale::setDefault(QLocale::c()); }
    void cleanupTestCase() { QLocale::setDefault(QLocale::c()); }

    void tokensStandWhereTyped();
    void shownDecimals_data();
    void shownDecimals();
    void steppingChangesOnlyThatNumber_data();
    void steppingChangesOnlyThatNumber();
    void steppingKeepsEveryOtherCharacter();
    void wrongTokensAreNotStepped();
    void splineFieldsStepAsOneUndoStepEach();
    void steppedKnotsOutOfOrderShowTheProblem();
    void stepTextFollowsTheLanguage();
    void segmentExampleKG202();
};

void TestStepFields::tokensStandWhereTyped()
{
    const QLocale lv(QLocale::Latvian, QLocale::Latvia);
    const QString text = QStringLiteral("3;  2 −1 0,5");
    const auto tokens = kontur::numberListTokens(text, lv);
    QCOMPARE(tokens.size(), std::size_t(4));
    QCOMPARE(text.mid(tokens[2].start, tokens[2].length), QStringLiteral("−1"));
    QCOMPARE(tokens[2].value, -1.0);
    QCOMPARE(text.mid(tokens[3].start, tokens[3].length), QStringLiteral("0,5"));
    QCOMPARE(tokens[3].value, 0.5);
    QCOMPARE(tokens[3].decimals, 1);
    // In English the comma separates: "0,5" is two numbers, as parseNumberList reads it.
    QCOMPARE(kontur::numberListTokens(QStringLiteral("0,5 1"), QLocale::c()).size(), std::size_t(3));
}

void TestStepFields::shownDecimals_data()
{
    QTest::addColumn<QString>("token");
    QTest::addColumn<int>("decimals");
    QTest::newRow("integer") << QStringLiteral("3") << 0;
    QTest::newRow("comma") << QStringLiteral("0,5") << 1;
    QTest::newRow("point in a comma language") << QStringLiteral("2.75") << 2;
    QTest::newRow("exponent") << QStringLiteral("1,5e-2") << 3;
    QTest::newRow("large exponent") << QStringLiteral("2e3") << 0;
    QTest::newRow("minus") << QStringLiteral("−0,0385") << 4;
}

void TestStepFields::shownDecimals()
{
    QFETCH(QString, token);
    QFETCH(int, decimals);
    QCOMPARE(kontur::shownDecimals(token, QLocale(QLocale::Slovak, QLocale::Slovakia)), decimals);
}

void TestStepFields::steppingChangesOnlyThatNumber_data()
{
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("index");
    QTest::addColumn<int>("direction");
    QTest::addColumn<QString>("stepped");
    QTest::newRow("integer up") << QStringLiteral("3 2 -1 0,5") << 1 << 1 << QStringLiteral("3 3 -1 0,5");
    QTest::newRow("tenth down") << QStringLiteral("3 2 -1 0,5") << 3 << -1 << QStringLiteral("3 2 -1 0,4");
    QTest::newRow("to zero, no minus") << QStringLiteral("0,1 2") << 0 << -1 << QStringLiteral("0,0 2");
    QTest::newRow("below zero") << QStringLiteral("0,0 2") << 0 << -1 << QStringLiteral("-0,1 2");
    QTest::newRow("hundredth carries") << QStringLiteral("1,99") << 0 << 1 << QStringLiteral("2,00");
    // Four decimals shown: stepped by 0,01 (kMaxStepDecimals), the decimals kept.
    QTest::newRow("fine value, visible step") << QStringLiteral("0,0385 1") << 0 << 1 << QStringLiteral("0,0485 1");
    QTest::newRow("point typed") << QStringLiteral("2.5; 1") << 0 << 1 << QStringLiteral("2,6; 1");
}

void TestStepFields::steppingChangesOnlyThatNumber()
{
    QFETCH(QString, text);
    QFETCH(int, index);
    QFETCH(int, direction);
    QFETCH(QString, stepped);
    const QLocale sk(QLocale::Slovak, QLocale::Slovakia);
    QCOMPARE(kontur::stepListNumber(text, sk, index, direction, 2), stepped);
}

void TestStepFields::steppingKeepsEveryOtherCharacter()
{
    // A property over many typed lists: the text outside the stepped number is the same to the
    // character, and the stepped number reads back as the old one plus or minus its step.
    const QLocale ru(QLocale::Russian, QLocale::Russia);
    const QStringList lists = {QStringLiteral("1;2;  3,25"), QStringLiteral(" −4,5  6e-1 ; 7 "),
                               QStringLiteral("0 0,333 12,5 100"), QStringLiteral("1.5 2.25")};
    for (const QString &text : lists) {
        const auto tokens = kontur::numberListTokens(text, ru);
        for (int i = 0; i < static_cast<int>(tokens.size()); ++i) {
            for (int direction : {-1, 1}) {
                const QString stepped = kontur::stepListNumber(text, ru, i, direction, 2);
                QVERIFY(!stepped.isEmpty());
                const auto after = kontur::numberListTokens(stepped, ru);
                QCOMPARE(after.size(), tokens.size());
                QCOMPARE(stepped.left(tokens[i].start), text.left(tokens[i].start));
                QCOMPARE(stepped.mid(after[i].start + after[i].length), text.mid(tokens[i].start + tokens[i].length));
                const double step = kontur::stepFor(tokens[i], 2);
                QVERIFY2(std::abs(after[i].value - (tokens[i].value + direction * step)) < 1e-9,
                         qPrintable(text + QStringLiteral(" → ") + stepped));
            }
        }
    }
}

void TestStepFields::wrongTokensAreNotStepped()
{
    const QLocale lv(QLocale::Latvian, QLocale::Latvia);
    QVERIFY(kontur::stepListNumber(QStringLiteral("1 x 3"), lv, 1, 1, 2).isEmpty());
    QVERIFY(kontur::stepListNumber(QStringLiteral("1 x 3"), lv, 3, 1, 2).isEmpty());
    QVERIFY(kontur::stepListNumber(QStringLiteral("1 x 3"), lv, -1, 1, 2).isEmpty());
    // The other numbers still step, the wrong token stays as typed.
    QCOMPARE(kontur::stepListNumber(QStringLiteral("1 x 3"), lv, 2, 1, 2), QStringLiteral("1 x 4"));
}

void TestStepFields::splineFieldsStepAsOneUndoStepEach()
{
    QLocale::setDefault(QLocale(QLocale::Slovak, QLocale::Slovakia));
    FunctionSplinePlot plot;
    plot.refreshTexts();
    QCOMPARE(plot.valuesText(), QStringLiteral("3 2 -1 0,5"));
    QCOMPARE(plot.numberCount(FunctionSplinePlot::ValuesField), 4);
    QCOMPARE(plot.numberStart(FunctionSplinePlot::ValuesField, 3), 7);
    QCOMPARE(plot.numberEnd(FunctionSplinePlot::ValuesField, 3), 10);
    QCOMPARE(plot.numberStart(FunctionSplinePlot::ValuesField, 4), -1);
    const double before = plot.splineAt(1.0);
    QCOMPARE(before, 2.0);

    // A value typed but not drawn yet, then another value stepped: the typed one stays as typed and
    // both are drawn.
    plot.setValuesText(QStringLiteral("3 2 -1 0,75"));
    QVERIFY(plot.stepNumber(FunctionSplinePlot::ValuesField, 1, 1));
    QCOMPARE(plot.valuesText(), QStringLiteral("3 3 -1 0,75"));
    QCOMPARE(plot.input().values, (std::vector<double>{3, 3, -1, 0.75}));
    QCOMPARE(plot.splineAt(1.0), 3.0);
    QVERIFY(plot.error().isEmpty());
    QVERIFY(plot.stepNumber(FunctionSplinePlot::ValuesField, 3, -1));
    QCOMPARE(plot.valuesText(), QStringLiteral("3 3 -1 0,74"));
    QCOMPARE(plot.input().values.back(), 0.74);

    // The interval's end and an end derivative.
    QCOMPARE(plot.intervalText(), QStringLiteral("0 3"));
    QVERIFY(plot.stepNumber(FunctionSplinePlot::IntervalField, 1, -1));
    QCOMPARE(plot.input().b, 2.0);
    QCOMPARE(plot.splineAt(2.0), 0.74);
    QVERIFY(plot.stepNumber(FunctionSplinePlot::DerivativesField, 0, 1));
    QCOMPARE(plot.input().derivatives.front(), 1.0);
    QVERIFY(std::abs(plot.knotSlopes().front() - 1.0) < 1e-12);

    // Each tap is one undo step, back to the state before the first.
    for (int i = 0; i < 4; ++i)
        plot.undo();
    QCOMPARE(plot.input().values, (std::vector<double>{3, 2, -1, 0.5}));
    QCOMPARE(plot.input().b, 3.0);
    QCOMPARE(plot.input().derivatives.front(), 0.0);
    QCOMPARE(plot.splineAt(1.0), before);
}

void TestStepFields::steppedKnotsOutOfOrderShowTheProblem()
{
    QLocale::setDefault(QLocale(QLocale::Latvian, QLocale::Latvia));
    FunctionSplinePlot plot;
    plot.setMethod(FunctionSplinePlot::Natural);
    plot.setUniformKnots(false);
    plot.refreshTexts();
    QCOMPARE(plot.knotsText(), QStringLiteral("0 1 2 3"));
    // Knot 1 stepped onto knot 2: the problem is shown, the text is kept as stepped, the curve as drawn.
    QVERIFY(plot.stepNumber(FunctionSplinePlot::KnotsField, 1, 1));
    QCOMPARE(plot.knotsText(), QStringLiteral("0 2 2 3"));
    QVERIFY(!plot.error().isEmpty());
    QCOMPARE(plot.knotX(), (std::vector<double>{0, 1, 2, 3}));
    // One tap back and it is drawn again.
    QVERIFY(plot.stepNumber(FunctionSplinePlot::KnotsField, 1, -1));
    QVERIFY(plot.error().isEmpty());
    QVERIFY(plot.stepNumber(FunctionSplinePlot::KnotsField, 2, -1));
    QCOMPARE(plot.knotsText(), QStringLiteral("0 1 1 3"));
    QVERIFY(!plot.error().isEmpty());
}

void TestStepFields::stepTextFollowsTheLanguage()
{
    QLocale::setDefault(QLocale(QLocale::Bulgarian, QLocale::Bulgaria));
    FunctionSplinePlot plot;
    plot.refreshTexts();
    QCOMPARE(plot.stepText(FunctionSplinePlot::ValuesField, 0), QStringLiteral("1"));
    QCOMPARE(plot.stepText(FunctionSplinePlot::ValuesField, 3), QStringLiteral("0,1"));
    QCOMPARE(plot.stepText(FunctionSplinePlot::ValuesField, 4), QString());
    QLocale::setDefault(QLocale::c());
    plot.refreshTexts();
    QCOMPARE(plot.stepText(FunctionSplinePlot::ValuesField, 3), QStringLiteral("0.1"));
    // Runge's samples show four decimals; a tap moves them by 0,01, which the plot shows.
    plot.loadRungeExample(11);
    QCOMPARE(plot.stepText(FunctionSplinePlot::ValuesField, 1), QStringLiteral("0.01"));
}

void TestStepFields::segmentExampleKG202()
{
    PracticumPlot plot;
    plot.loadSegmentExample();
    QCOMPARE(plot.mode(), PracticumPlot::FunctionSegment);
    QVERIFY(plot.error().isEmpty());
    // k0 = 1, k1 = −1, t = 100: a3 = 3·0/100² − (2 − 1)/100 = −0,01, a4 = 0 + (1 − 1)/100² = 0.
    QVERIFY2(plot.details().contains(QStringLiteral("k0 = 1.000; k1 = -1.000; a3 = -0.010; a4 = 0.000")),
             qPrintable(plot.details()));
    const QPolygonF &line = plot.polyline();
    QCOMPARE(line.size(), plot.linesPerSegment() + 1);
    const QPointF top = line[line.size() / 2];
    QVERIFY(std::abs(top.x() - 50) < 1e-12 && std::abs(top.y() - 25) < 1e-12);

    // The same grips as a parametric segment: unit tangents (0,707; ±0,707), t2 = 100, a lower arch.
    plot.setMode(PracticumPlot::ParametricSegment);
    plot.loadSegmentExample();
    QCOMPARE(plot.mode(), PracticumPlot::ParametricSegment);
    QVERIFY2(plot.details().contains(QStringLiteral("t2 = |P1 − P0| = 100.000; P0′ = (0.707; 0.707); P1′ = (0.707; -0.707)")),
             qPrintable(plot.details()));
    const QPointF middle = plot.polyline()[plot.polyline().size() / 2];
    QVERIFY(std::abs(middle.x() - 50) < 1e-9);
    QVERIFY(std::abs(middle.y() - 25 / std::sqrt(2.0)) < 1e-9); // 17,68
    // One undo step back to the parametric default.
    plot.undo();
    QCOMPARE(plot.input().points.back(), QPointF(4, 1));
}

QTEST_GUILESS_MAIN(TestStepFields)
#include "tst_stepfields.moc"
