// Numbers at every scale in the model layer (issue #17): the coordinates table's cells change only
// what was typed, in the C, Latvian and Russian number formats; copying gives every digit; nothing
// that is not finite ever gets into the document; lengths are asked relative to the curve's size.
#include "../curveids.h"
#include "models/controllers/documentfiles.h"
#include "models/controllers/editcontroller.h"
#include "models/document/document.h"
#include "models/itemmodels/curvelistmodel.h"
#include "models/itemmodels/pointlistmodel.h"
#include "models/text/numbers.h"

#include <QAbstractItemModelTester>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using kontur::CurveKind;
using kontur::EditController;
using kontur::Message;
using kontur::geo::Point;

namespace {

QVariantList rows(const std::vector<Point> &points)
{
    QVariantList list;
    for (const Point &p : points)
        list << QVariant(QVariantList{p.x(), p.y()});
    return list;
}

// One typed cell of the table, as the QML sends it: {row, x} or {row, y}.
QVariantMap cell(int row, const char *axis, const QString &text)
{
    return {{QStringLiteral("row"), row}, {QString::fromLatin1(axis), text}};
}

// Every curve of the document holds only finite rows and segments.
bool documentFinite(const EditController &editor)
{
    for (const kontur::Curve &curve : editor.document()->curves())
        if (!curve.isFinite())
            return false;
    return true;
}

// A composite curve from its control vector as given (no construction rule), for overflow cases
// whose handles lie far from their knots.
kontur::Curve composite(std::vector<Point> control)
{
    const int knots = static_cast<int>(control.size() + 2) / 3;
    auto parts = kontur::geo::CompositeCurve::fromParts(
        std::move(control), std::vector<kontur::geo::NodeType>(static_cast<std::size_t>(knots)), false);
    Q_ASSERT(parts.ok());
    auto curve = kontur::Curve::makeComposite(std::move(parts.value()));
    Q_ASSERT(curve.ok());
    return std::move(curve.value());
}

constexpr double kMax = std::numeric_limits<double>::max();

} // namespace

class TestNumbers final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void cleanup() { QLocale::setDefault(QLocale::c()); }

    void typedCellKeepsTheOtherAxis_data();
    void typedCellKeepsTheOtherAxis();
    void typedCellsAreOneUndoStep();
    void typedKnotCarriesHandlesExactly();
    void typedHandleWithItsKnotEndsWhereTyped();
    void typedInEveryLanguage_data();
    void typedInEveryLanguage();
    void typedListsInEveryLanguage();
    void formattedNumbersReadBackInEveryLanguage();
    void formattedNumbers();
    void badTypedNumbersAreRefused_data();
    void badTypedNumbersAreRefused();
    void shownNumbers_data();
    void shownNumbers();
    void copyGivesEveryDigit_data();
    void copyGivesEveryDigit();
    void overflowingEditsAreRefused();
    void overflowingCreationIsRefused();
    void extremeScalesNeverHoldNonFinite();
    void importOfOverflowingCurveIsRefused();
    void lengthIsRelativeToSize_data();
    void lengthIsRelativeToSize();
};

void TestNumbers::typedCellKeepsTheOtherAxis_data()
{
    QTest::addColumn<QString>("locale");
    QTest::addColumn<QString>("axis");
    QTest::addColumn<QString>("typed");
    QTest::addColumn<double>("expected");
    // Decimal comma and a no-break space as group separator in Latvian and Russian.
    const QString nbsp(QChar(0x00A0));
    for (const QString &locale : {QStringLiteral("C"), QStringLiteral("lv_LV"), QStringLiteral("ru_RU")}) {
        const bool comma = locale != QLatin1String("C");
        const auto text = [&](const char *c) {
            QString t = QString::fromLatin1(c);
            return comma ? t.replace(QLatin1Char('.'), QLatin1Char(',')) : t;
        };
        const auto row = [&](const char *name) -> QTestData & {
            return QTest::newRow(qPrintable(locale + QLatin1Char(' ') + QLatin1String(name)));
        };
        row("x 20.123456789") << locale << "x" << text("20.123456789") << 20.123456789;
        row("y 1e300") << locale << "y" << text("1e300") << 1e300;
        row("x -0.000001234") << locale << "x" << text("-0.000001234") << -0.000001234;
        row("y -1.5e-300") << locale << "y" << text("-1.5e-300") << -1.5e-300;
        row("y 12345678.25") << locale << "y" << text("12345678.25") << 12345678.25;
        if (comma) // as the table shows it, with group separators
            row("x 12 345 678,25") << locale << "x"
                                   << (QStringLiteral("12") + nbsp + QStringLiteral("345") + nbsp +
                                       QStringLiteral("678,25"))
                                   << 12345678.25;
        // A decimal point is taken in every language (as in files).
        row("x 7.000000000000001 with a point")
            << locale << "x" << QStringLiteral("7.000000000000001") << 7.000000000000001;
    }
}

void TestNumbers::typedCellKeepsTheOtherAxis()
{
    QFETCH(QString, locale);
    QFETCH(QString, axis);
    QFETCH(QString, typed);
    QFETCH(double, expected);
    QLocale::setDefault(QLocale(locale));
    EditController editor;
    QAbstractItemModelTester tester(editor.points());
    // The table shows 20.123 and 20.123 for these (three decimals); they hold every digit.
    QVERIFY(editor.placement()->createFromCoordinates(
        static_cast<int>(CurveKind::Bezier),
        rows({{20.123456789, 20.987654321}, {-0.000004321, 1e-7}, {30.5, 1234567.8765432}, {40, 0.1}})));
    QSignalSpy changed(editor.points(), &QAbstractItemModel::dataChanged);
    QVERIFY(editor.commands()->applyEdits(kontur::test::idAt(editor, 0), {cell(1, qPrintable(axis), typed)}));
    const kontur::Curve &curve = editor.document()->curve(0);
    const Point p = curve.definingPoint(1);
    if (axis == QLatin1String("x")) {
        QCOMPARE(p.x(), expected);
        QCOMPARE(p.y(), 1e-7); // untouched: the double, not "0.000"
    } else {
        QCOMPARE(p.x(), -0.000004321); // untouched: not "-4.321e-06"
        QCOMPARE(p.y(), expected);
    }
    // The other rows are as they were, to the last bit.
    QCOMPARE(curve.definingPoint(0), Point(20.123456789, 20.987654321));
    QCOMPARE(curve.definingPoint(2), Point(30.5, 1234567.8765432));
    QCOMPARE(curve.definingPoint(3), Point(40, 0.1));
    QVERIFY(!changed.isEmpty());
    QVERIFY(editor.message().isEmpty());
}

void TestNumbers::typedCellsAreOneUndoStep()
{
    QLocale::setDefault(QLocale(QStringLiteral("lv_LV")));
    EditController editor;
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::Bezier),
                                                      rows({{20.123456789, 20.123456789}, {1, 2}, {3, 4}, {5, 6}})));
    const int before = editor.undoStack()->index();
    // X of row 0 and Y of row 2 typed; everything else keeps its double.
    QVERIFY(editor.commands()->applyEdits(
        kontur::test::idAt(editor, 0), {cell(0, "x", QStringLiteral("21,5")), cell(2, "y", QStringLiteral("-4,25"))}));
    QCOMPARE(editor.undoStack()->index(), before + 1);
    const kontur::Curve &curve = editor.document()->curve(0);
    QCOMPARE(curve.definingPoint(0), Point(21.5, 20.123456789));
    QCOMPARE(curve.definingPoint(2), Point(3, -4.25));
    editor.undo();
    QCOMPARE(editor.document()->curve(0).definingPoint(0), Point(20.123456789, 20.123456789));
    QCOMPARE(editor.document()->curve(0).definingPoint(2), Point(3, 4));
    editor.redo();
    QCOMPARE(editor.document()->curve(0).definingPoint(0), Point(21.5, 20.123456789));
    // Nothing typed: nothing to do, no undo step.
    QVERIFY(editor.commands()->applyEdits(kontur::test::idAt(editor, 0), {QVariantMap{{QStringLiteral("row"), 1}}}));
    QCOMPARE(editor.undoStack()->index(), before + 1);
}

void TestNumbers::typedKnotCarriesHandlesExactly()
{
    // A composite knot's typed X moves its handles by the same amount; their Y, and the knot's, stay.
    EditController editor;
    editor.commands()->addCurves(
        {composite({{0.1, 0.7}, {1.1, 2.3}, {3.3, 2.9}, {4.1, 0.3}, {5.7, -2.1}, {7.9, -1.3}, {9.3, 0.9}})},
        QStringLiteral("test"));
    // Knot 1 is row 3; its handles are rows 2 and 4.
    QVERIFY(editor.commands()->applyEdits(kontur::test::idAt(editor, 0), {cell(3, "x", QStringLiteral("4.6"))}));
    const kontur::Curve &curve = editor.document()->curve(0);
    QCOMPARE(curve.definingPoint(3), Point(4.6, 0.3));
    QCOMPARE(curve.definingPoint(2).y(), 2.9);
    QCOMPARE(curve.definingPoint(4).y(), -2.1);
    QVERIFY(std::abs(curve.definingPoint(2).x() - 3.8) < 1e-15);
    QVERIFY(std::abs(curve.definingPoint(4).x() - 6.2) < 1e-15);
}

void TestNumbers::typedHandleWithItsKnotEndsWhereTyped()
{
    // Handle row 2 and its knot (row 3) typed in one OK, the handle listed first: the knot moves
    // first, then the handle goes exactly where it was typed (it used to be shifted by the knot's move).
    EditController editor;
    editor.commands()->addCurves(
        {composite({{0.1, 0.7}, {1.1, 2.3}, {3.3, 2.9}, {4.1, 0.3}, {5.7, -2.1}, {7.9, -1.3}, {9.3, 0.9}})},
        QStringLiteral("test"));
    QVERIFY(editor.commands()->applyEdits(kontur::test::idAt(editor, 0),
                                          {QVariantMap{{QStringLiteral("row"), 2},
                                                       {QStringLiteral("x"), QStringLiteral("3")},
                                                       {QStringLiteral("y"), QStringLiteral("2.5")}},
                                           cell(3, "x", QStringLiteral("4.6"))}));
    const kontur::Curve &curve = editor.document()->curve(0);
    QCOMPARE(curve.definingPoint(3), Point(4.6, 0.3));
    QCOMPARE(curve.definingPoint(2), Point(3.0, 2.5));
    editor.undo();
    QCOMPARE(editor.document()->curve(0).definingPoint(2), Point(3.3, 2.9));
    QCOMPARE(editor.document()->curve(0).definingPoint(3), Point(4.1, 0.3));
}

// One parser for every number a person types (table cells, the seam allowance, the perspective's
// rectangle, the trace tolerance, the function spline's lists): the same texts in all five languages,
// as people type them: decimal comma or point, groups of thousands with a plain, no-break or narrow
// no-break space, exponents, a typographic minus; a number beyond doubles is too large, never infinite.
void TestNumbers::typedInEveryLanguage_data()
{
    QTest::addColumn<QString>("locale");
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("parsed");
    QTest::addColumn<double>("value");
    const auto number = static_cast<int>(kontur::Parsed::Number);
    const auto notValid = static_cast<int>(kontur::Parsed::NotValid);
    const auto tooLarge = static_cast<int>(kontur::Parsed::TooLarge);
    for (const char *code : {"lv_LV", "sk_SK", "bg_BG", "ru_RU"}) {
        const QString l = QString::fromLatin1(code);
        QTest::addRow("%s decimal comma", code) << l << QStringLiteral("0,5") << number << 0.5;
        QTest::addRow("%s decimal point", code) << l << QStringLiteral("0.5") << number << 0.5;
        QTest::addRow("%s group space", code) << l << QStringLiteral("1 234,5") << number << 1234.5;
        QTest::addRow("%s group no-break", code) << l << QStringLiteral("1\u00a0234,5") << number << 1234.5;
        QTest::addRow("%s group narrow", code) << l << QStringLiteral("12\u202f345\u202f678") << number << 12345678.0;
        QTest::addRow("%s typographic minus", code) << l << QStringLiteral("\u22122,25") << number << -2.25;
        QTest::addRow("%s exponent", code) << l << QStringLiteral("1,5e-3") << number << 1.5e-3;
        QTest::addRow("%s spaces around", code) << l << QStringLiteral("  7 ") << number << 7.0;
        QTest::addRow("%s too large", code) << l << QStringLiteral("1e400") << tooLarge << 0.0;
        QTest::addRow("%s word", code) << l << QStringLiteral("abc") << notValid << 0.0;
        QTest::addRow("%s two numbers", code) << l << QStringLiteral("1,5 2") << notValid << 0.0;
        QTest::addRow("%s infinity", code) << l << QStringLiteral("inf") << notValid << 0.0;
    }
    const QString en = QStringLiteral("en_US");
    QTest::addRow("en decimal point") << en << QStringLiteral("0.5") << number << 0.5;
    QTest::addRow("en grouping") << en << QStringLiteral("1,234.5") << number << 1234.5;
    QTest::addRow("en typographic minus") << en << QStringLiteral("\u22120.125") << number << -0.125;
    QTest::addRow("en exponent") << en << QStringLiteral("-2.5E+3") << number << -2500.0;
    QTest::addRow("en too large") << en << QStringLiteral("-1e309") << tooLarge << 0.0;
    QTest::addRow("en empty") << en << QStringLiteral(" ") << notValid << 0.0;
}

void TestNumbers::typedInEveryLanguage()
{
    QFETCH(QString, locale);
    QFETCH(QString, text);
    QFETCH(int, parsed);
    QFETCH(double, value);
    QLocale::setDefault(QLocale(locale));
    double out = 0.0;
    QCOMPARE(static_cast<int>(kontur::parseNumber(QVariant(text), out)), parsed);
    if (parsed == static_cast<int>(kontur::Parsed::Number))
        QCOMPARE(out, value);
    // The same through the locale given explicitly (the function spline's fields).
    double again = 0.0;
    QCOMPARE(static_cast<int>(kontur::parseNumber(text, QLocale(locale), again)), parsed);
    if (parsed == static_cast<int>(kontur::Parsed::Number))
        QCOMPARE(again, value);
}

void TestNumbers::typedListsInEveryLanguage()
{
    std::vector<double> out;
    for (const char *code : {"lv_LV", "sk_SK", "bg_BG", "ru_RU"}) {
        const QLocale locale{QString::fromLatin1(code)};
        QCOMPARE(kontur::parseNumberList(QStringLiteral("3; 2 \u22121;0,5"), locale, out), kontur::Parsed::Number);
        QCOMPARE(out, (std::vector<double>{3.0, 2.0, -1.0, 0.5}));
        QString bad;
        QCOMPARE(kontur::parseNumberList(QStringLiteral("3 x 1"), locale, out, &bad), kontur::Parsed::NotValid);
        QCOMPARE(bad, QStringLiteral("x"));
        QCOMPARE(kontur::parseNumberList(QStringLiteral("1 1e999"), locale, out, &bad), kontur::Parsed::TooLarge);
    }
    const QLocale en{QStringLiteral("en_US")};
    QCOMPARE(kontur::parseNumberList(QStringLiteral("3, 2,-1;0.5"), en, out), kontur::Parsed::Number);
    QCOMPARE(out, (std::vector<double>{3.0, 2.0, -1.0, 0.5}));
}

// The one formatter against the one parser: in all five languages, a number written with `d` decimals
// (grouped or not) reads back within half a unit of its last decimal, over random values and scales; a
// list written without groups reads back as the list.
void TestNumbers::formattedNumbersReadBackInEveryLanguage()
{
    std::mt19937_64 random(37);
    std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
    std::uniform_int_distribution<int> exponent(-4, 9), decimals(0, 6);
    for (const char *code : {"en_US", "lv_LV", "sk_SK", "bg_BG", "ru_RU"}) {
        const QLocale locale{QString::fromLatin1(code)};
        std::vector<double> list;
        for (int i = 0; i < 400; ++i) {
            const double value = mantissa(random) * std::pow(10.0, exponent(random));
            const int d = decimals(random);
            for (const bool grouping : {true, false}) {
                const QString text = kontur::fixedNumber(value, d, locale, {.grouping = grouping});
                double back = 0.0;
                QVERIFY2(kontur::parseNumber(text, locale, back) == kontur::Parsed::Number,
                         qPrintable(QStringLiteral("%1: %2").arg(QString::fromLatin1(code), text)));
                QVERIFY2(std::abs(back - value) <= 0.5 * std::pow(10.0, -d) * (1 + 1e-9) + 1e-12 * std::abs(value),
                         qPrintable(QStringLiteral("%1: %2 for %3").arg(QString::fromLatin1(code), text).arg(value)));
            }
            if (i < 20)
                list.push_back(std::round(value * 1e4) / 1e4);
        }
        QStringList parts;
        for (const double v : list)
            parts << kontur::fixedNumber(v, 4, locale, {.grouping = false, .trailingZeros = false});
        std::vector<double> back;
        QCOMPARE(kontur::parseNumberList(parts.join(QLatin1Char(' ')), locale, back), kontur::Parsed::Number);
        QCOMPARE(back.size(), list.size());
        for (std::size_t i = 0; i < list.size(); ++i)
            QVERIFY(std::abs(back[i] - list[i]) <= 1e-9 * std::max(1.0, std::abs(list[i])));
    }
}

void TestNumbers::formattedNumbers()
{
    const QLocale en{QStringLiteral("en_US")}, lv{QStringLiteral("lv_LV")}, ru{QStringLiteral("ru_RU")};
    QCOMPARE(kontur::fixedNumber(-0.0004, 3, en), QStringLiteral("0.000")); // no "-0.000"
    QCOMPARE(kontur::fixedNumber(-0.0006, 3, en), QStringLiteral("-0.001"));
    QCOMPARE(kontur::fixedNumber(12345.5, 2, en), QStringLiteral("12,345.50"));
    QCOMPARE(kontur::fixedNumber(12345.5, 2, en, {.grouping = false}), QStringLiteral("12345.50"));
    QCOMPARE(kontur::fixedNumber(2.5, 4, lv, {.grouping = false, .trailingZeros = false}), QStringLiteral("2,5"));
    QCOMPARE(kontur::fixedNumber(3.0, 4, lv, {.grouping = false, .trailingZeros = false}), QStringLiteral("3"));
    QCOMPARE(kontur::fixedNumber(-0.00001, 4, ru, {.trailingZeros = false}), QStringLiteral("0"));
    QCOMPARE(kontur::fixedNumber(std::numeric_limits<double>::infinity(), 2, en), QStringLiteral("—"));
    QCOMPARE(kontur::significantNumber(1234567.0, 3, en), QStringLiteral("1.23E+6"));
    QCOMPARE(kontur::significantNumber(0.000123, 3, ru), QStringLiteral("0,000123"));
    QCOMPARE(kontur::significantNumber(130.0, 3, lv), QStringLiteral("130"));
    QCOMPARE(kontur::significantNumber(std::nan(""), 3, en), QStringLiteral("—"));
}

void TestNumbers::badTypedNumbersAreRefused_data()
{
    QTest::addColumn<QString>("typed");
    QTest::addColumn<int>("message");
    QTest::addRow("empty") << QString() << static_cast<int>(Message::FillAllValues);
    QTest::addRow("letters") << QStringLiteral("abc") << static_cast<int>(Message::FillAllValues);
    QTest::addRow("inf") << QStringLiteral("inf") << static_cast<int>(Message::FillAllValues);
    QTest::addRow("nan") << QStringLiteral("nan") << static_cast<int>(Message::FillAllValues);
    QTest::addRow("1e400") << QStringLiteral("1e400") << static_cast<int>(Message::OutOfRange);
    QTest::addRow("-2e308") << QStringLiteral("-2e308") << static_cast<int>(Message::OutOfRange);
}

void TestNumbers::badTypedNumbersAreRefused()
{
    QFETCH(QString, typed);
    QFETCH(int, message);
    EditController editor;
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::Bezier),
                                                      rows({{0, 0}, {1, 2}, {3, 4}, {5, 6}})));
    const int before = editor.undoStack()->index();
    QVERIFY(!editor.commands()->applyEdits(kontur::test::idAt(editor, 0), {cell(1, "y", typed)}));
    QCOMPARE(static_cast<int>(editor.message().id), message);
    QCOMPARE(editor.document()->curve(0).definingPoint(1), Point(1, 2));
    QCOMPARE(editor.undoStack()->index(), before);
    // The same text refused where a curve is created from coordinates.
    QVERIFY(!editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::Bezier),
                                                       QVariantList{QVariantList{0, 0}, QVariantList{1, typed}}));
    QCOMPARE(static_cast<int>(editor.message().id), message);
    QCOMPARE(editor.document()->curveCount(), 1);
}

void TestNumbers::shownNumbers_data()
{
    QTest::addColumn<QString>("locale");
    QTest::addColumn<double>("value");
    QTest::addColumn<int>("decimals");
    QTest::addColumn<QString>("shown");
    const QString nbsp(QChar(0x00A0));
    QTest::addRow("C 20.123456789") << "C" << 20.123456789 << 3 << "20.123";
    QTest::addRow("C 0") << "C" << 0.0 << 3 << "0.000";
    QTest::addRow("C 1e300") << "C" << 1e300 << 3 << "1e+300";
    QTest::addRow("C -0.000001234") << "C" << -0.000001234 << 3 << "-1.23e-6";
    QTest::addRow("C 1e7") << "C" << 10000123.456789 << 3 << "10000123";
    QTest::addRow("C 12345.678") << "C" << 12345.678 << 3 << "12345.68";
    QTest::addRow("C 999.9996") << "C" << 999.9996 << 3 << "1000.000";
    QTest::addRow("C -123456.789 length") << "C" << -123456.789 << 1 << "-123456.8";
    QTest::addRow("C 1.234567e9") << "C" << 1.234567e9 << 3 << "1.23e+9";
    QTest::addRow("C -1.23456e-300") << "C" << -1.23456e-300 << 3 << "-1.23e-300";
    QTest::addRow("C 1.5e150 length") << "C" << 1.5e150 << 1 << "1.5e+150";
    QTest::addRow("C infinity") << "C" << std::numeric_limits<double>::infinity() << 3 << "—";
    QTest::addRow("lv 20.123456789") << "lv_LV" << 20.123456789 << 3 << "20,123";
    QTest::addRow("lv 1e7") << "lv_LV" << 10000123.456789 << 3 << (QStringLiteral("10") + nbsp + "000" + nbsp + "123");
    QTest::addRow("ru 1234.5678") << "ru_RU" << 1234.5678 << 3 << (QStringLiteral("1") + nbsp + "234,568");
    QTest::addRow("lv -0.000001234") << "lv_LV" << -0.000001234 << 3 << "-1,23E-6";
    QTest::addRow("ru 1e300") << "ru_RU" << 1e300 << 3 << "1E+300";
}

void TestNumbers::shownNumbers()
{
    QFETCH(QString, locale);
    QFETCH(double, value);
    QFETCH(int, decimals);
    QFETCH(QString, shown);
    QLocale::setDefault(QLocale(locale));
    QCOMPARE(kontur::displayNumber(value, decimals), shown);
}

void TestNumbers::copyGivesEveryDigit_data()
{
    QTest::addColumn<QString>("locale");
    QTest::addColumn<QString>("text");
    QTest::addRow("C") << "C"
                       << "C0\t20.123456789\t1e+300\nC1\t-1.234e-06\t12345678.25\nC2\t0.1\t-1.5e-300\n";
    // Latvian writes the exponent with a capital E.
    QTest::addRow("lv") << "lv_LV"
                        << "C0\t20,123456789\t1E+300\nC1\t-1,234E-06\t12345678,25\nC2\t0,1\t-1,5E-300\n";
}

void TestNumbers::copyGivesEveryDigit()
{
    QFETCH(QString, locale);
    QFETCH(QString, text);
    QLocale::setDefault(QLocale(locale));
    EditController editor;
    QVERIFY(editor.placement()->createFromCoordinates(
        static_cast<int>(CurveKind::Bezier),
        rows({{20.123456789, 1e300}, {-0.000001234, 12345678.25}, {0.1, -1.5e-300}})));
    QCOMPARE(editor.commands()->coordinatesText(kontur::test::idAt(editor, 0)), text);
}

void TestNumbers::overflowingEditsAreRefused()
{
    EditController editor;
    // A composite curve whose first knot's handle lies 1e308 from it: moving the knot by more than
    // about 0.8e308 would carry the handle past the largest double.
    editor.commands()->addCurves({composite({{0, 0}, {1e308, 0}, {1.5e308, 1}, {1.6e308, 2}})}, QStringLiteral("test"));
    const kontur::Curve original = editor.document()->curve(0);
    const int before = editor.undoStack()->index();
    const auto unchanged = [&] {
        return editor.document()->curve(0).sameState(original) && editor.undoStack()->index() == before &&
               documentFinite(editor);
    };

    // Typed.
    QVERIFY(!editor.commands()->applyEdits(kontur::test::idAt(editor, 0), {cell(0, "x", QStringLiteral("1e308"))}));
    QCOMPARE(editor.message().id, Message::OutOfRange);
    QVERIFY(unchanged());

    // Dragged: nothing moves, and the canvas is never told of a change.
    editor.clearMessage();
    QSignalSpy rowsChanged(editor.document(), &kontur::Document::rowsChanged);
    QVERIFY(editor.beginDrag(QPointF(0, 0), 0.5));
    editor.dragTo(QPointF(1e308, 0));
    editor.endDrag();
    QCOMPARE(editor.message().id, Message::OutOfRange);
    QVERIFY(unchanged());
    QCOMPARE(rowsChanged.count(), 0);
    // A drag within range still works afterwards.
    QVERIFY(editor.beginDrag(QPointF(0, 0), 0.5));
    editor.dragTo(QPointF(0.5, 0.25));
    editor.endDrag();
    QCOMPARE(editor.document()->curve(0).definingPoint(0), Point(0.5, 0.25));
    editor.undo();
    QVERIFY(unchanged());

    // Nudged (arrow keys).
    kontur::test::selectAt(editor, 0, 0);
    QVERIFY(!editor.commands()->nudgeSelected(QPointF(1e308, 0)));
    QCOMPARE(editor.message().id, Message::OutOfRange);
    QVERIFY(unchanged());
    kontur::test::selectAt(editor, 0, 3);
    QVERIFY(!editor.commands()->nudgeSelected(QPointF(1.7e308, 0))); // the point itself past the largest double
    QVERIFY(unchanged());

    // "Add row" beyond a last point near the largest double: 2 × 1.7e308 − 0.
    EditController bezier;
    QVERIFY(
        bezier.placement()->createFromCoordinates(static_cast<int>(CurveKind::Bezier), rows({{0, 0}, {1.7e308, 1}})));
    kontur::test::selectAt(bezier, 0, 1);
    QVERIFY(!bezier.commands()->addRowAfterSelection());
    QCOMPARE(bezier.message().id, Message::OutOfRange);
    QCOMPARE(bezier.document()->curve(0).rowCount(), 2);
    QVERIFY(!bezier.commands()->insertPoint(kontur::test::idAt(bezier, 0), 1,
                                            QPointF(std::numeric_limits<double>::infinity(), 0)));
    QVERIFY(!bezier.commands()->insertPoint(kontur::test::idAt(bezier, 0), 1,
                                            QPointF(std::numeric_limits<double>::quiet_NaN(), 0)));
    QCOMPARE(bezier.document()->curve(0).rowCount(), 2);
    QVERIFY(documentFinite(bezier));
}

void TestNumbers::overflowingCreationIsRefused()
{
    // Values that are finite but beyond what the kind can compute with: refused or finite, never
    // held as NaN. A Bézier curve at the largest double is finite (its points are the rows).
    EditController editor;
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::Bezier),
                                                      rows({{-kMax, -kMax}, {kMax, kMax}})));
    QCOMPARE(editor.document()->curve(0).definingPoint(1), Point(kMax, kMax));
    // Taps at the largest double while placing: never a non-finite preview for the canvas.
    editor.startPlacing(static_cast<int>(CurveKind::Composite));
    for (const Point &p : {Point(-kMax, 0), Point(kMax, 0), Point(kMax, kMax), Point(-kMax, kMax)})
        editor.tap(QPointF(p.x(), p.y()), 1.0);
    for (const auto &segment : editor.placement()->pendingSegments())
        for (const Point &p : segment.controlPoints())
            QVERIFY(p.allFinite());
    const bool made = editor.placement()->finish();
    QVERIFY(made || editor.message().id == Message::OutOfRange || editor.message().id == Message::FitFailed);
    QVERIFY(documentFinite(editor));
    // Non-finite positions from a gesture are ignored.
    editor.startPlacing(static_cast<int>(CurveKind::Bezier));
    editor.tap(QPointF(std::numeric_limits<double>::infinity(), 0), 1.0);
    editor.tap(QPointF(std::numeric_limits<double>::quiet_NaN(), 0), 1.0);
    QCOMPARE(editor.placement()->pendingCount(), 0);
}

void TestNumbers::extremeScalesNeverHoldNonFinite()
{
    // Property: whatever is created, typed, dragged or nudged at any scale, the document stays finite
    // and what it accepted is what was given. Seeded, so that a failure can be repeated.
    std::mt19937 random(17);
    int accepted = 0;
    for (const double scale : {1e-300, 1e-170, 1e-6, 1.0, 1e6, 1e150, 1e160, 1e300, 1e307}) {
        std::uniform_real_distribution<double> unit(-1.0, 1.0);
        for (const CurveKind kind : {CurveKind::Bezier, CurveKind::Composite, CurveKind::NaturalSpline,
                                     CurveKind::CatmullRom, CurveKind::BSpline, CurveKind::Interpolating}) {
            EditController editor;
            std::vector<Point> points;
            const int count = kind == CurveKind::Interpolating ? 4 : 5;
            for (int i = 0; i < count; ++i)
                points.emplace_back(scale * (i + 0.5 * unit(random)), scale * unit(random));
            const bool made = editor.placement()->createFromCoordinates(static_cast<int>(kind), rows(points));
            QVERIFY2(documentFinite(editor), qPrintable(QStringLiteral("scale %1 kind %2").arg(scale).arg(int(kind))));
            if (!made)
                continue;
            ++accepted;
            // The placed points are exactly those given.
            const kontur::Curve &curve = editor.document()->curve(0);
            for (int i = 0; i < curve.placedCount(); ++i) {
                const Point placed = kind == CurveKind::Composite ? curve.composite().knot(i) : curve.definingPoint(i);
                QCOMPARE(placed, points[static_cast<std::size_t>(i)]);
            }
            // The length is finite and of the curve's magnitude.
            const double length = curve.length(0.0);
            QVERIFY2(std::isfinite(length) && length > 0.5 * scale && length < 100 * scale,
                     qPrintable(QStringLiteral("scale %1 kind %2 length %3").arg(scale).arg(int(kind)).arg(length)));
            // Typed, nudged and dragged by amounts of the scale and beyond it.
            for (const double factor : {0.5, 1e3, 1e300}) {
                const double amount = std::isfinite(scale * factor) ? scale * factor : kMax;
                (void)editor.commands()->applyEdits(kontur::test::idAt(editor, 0),
                                                    {cell(0, "x", QLocale::c().toString(amount, 'g', 17))});
                QVERIFY(documentFinite(editor));
                kontur::test::selectAt(editor, 0, 0);
                (void)editor.commands()->nudgeSelected(QPointF(amount, -amount));
                QVERIFY(documentFinite(editor));
                const Point at = editor.document()->curve(0).row(0).position;
                if (editor.beginDrag(QPointF(at.x(), at.y()), 1e-300 + std::abs(at.x()) * 1e-12)) {
                    editor.dragTo(QPointF(at.x() + amount, at.y() + amount));
                    editor.endDrag();
                }
                QVERIFY(documentFinite(editor));
            }
        }
    }
    // At least the Bézier curves (whose rows are their points) at every scale, and more.
    qInfo("%d of 54 curves accepted", accepted);
    QVERIFY2(accepted >= 9, qPrintable(QString::number(accepted)));
}

void TestNumbers::importOfOverflowingCurveIsRefused()
{
    // A points text of two Bézier control points at ±1.7e308 reads; a least-squares cubic through
    // knots there needs sums of squares beyond the largest double: refused with a message, or taken
    // finite — never held as NaN.
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("huge.txt"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write("-1.7e308 -1.7e308\n-1e308 1.7e308\n1e308 -1.7e308\n1.7e308 1.7e308\n1.5e308 0\n");
    file.close();
    for (const CurveKind kind :
         {CurveKind::Bezier, CurveKind::Composite, CurveKind::LeastSquares, CurveKind::NaturalSpline}) {
        EditController editor;
        kontur::DocumentFiles files;
        files.setEditor(&editor);
        const bool imported = files.importFile(QUrl::fromLocalFile(path), static_cast<int>(kind));
        QVERIFY(documentFinite(editor));
        if (imported) {
            QCOMPARE(editor.document()->curveCount(), 1);
        } else {
            QCOMPARE(editor.message().id, Message::FileReadError);
            QCOMPARE(editor.document()->curveCount(), 0);
        }
    }
}

void TestNumbers::lengthIsRelativeToSize_data()
{
    QTest::addColumn<double>("scale");
    QTest::addColumn<double>("offset");
    for (const double scale : {1e-300, 1e-6, 1.0, 1e7, 1e150, 1e300})
        QTest::addRow("scale %g", scale) << scale << 0.0;
    // Small curves far from the origin (micrometre CAD exports): the freeze of issue #17.
    QTest::addRow("1 at 1e7") << 1.0 << 1e7;
    QTest::addRow("1000 at 1e7") << 1000.0 << 1e7;
    QTest::addRow("1e6 at 1e7") << 1e6 << 1e7;
}

void TestNumbers::lengthIsRelativeToSize()
{
    QFETCH(double, scale);
    QFETCH(double, offset);
    EditController editor;
    QAbstractItemModelTester tester(editor.curves());
    // The parabola arc B(t) = (2t, 2t(1 - t)), of length √2 + asinh(1) = 2.295587149392638…, and
    // the cubic line (0,0)…(9,12) of length 15 (exact control points at every offset used here).
    QVERIFY(editor.placement()->createFromCoordinates(
        static_cast<int>(CurveKind::Bezier),
        rows({{offset, offset}, {offset + scale, offset + scale}, {offset + 2 * scale, offset}})));
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(CurveKind::Bezier),
                                                      rows({{offset, offset},
                                                            {offset + 3 * scale, offset + 4 * scale},
                                                            {offset + 6 * scale, offset + 8 * scale},
                                                            {offset + 9 * scale, offset + 12 * scale}})));
    const double parabola = 2.2955871493926381 * scale;
    const double line = 15.0 * scale;
    const auto length = [&](int row) {
        return editor.curves()->data(editor.curves()->index(row), kontur::CurveListModel::LengthRole).toDouble();
    };
    // Asked 1e-9 of the size (the control polygon: 2√2 and 15 times the scale).
    QVERIFY2(std::abs(length(0) - parabola) <= 1e-9 * 2.9 * scale, qPrintable(QString::number(length(0), 'g', 17)));
    QVERIFY2(std::abs(length(1) - line) <= 1e-9 * 15 * scale, qPrintable(QString::number(length(1), 'g', 17)));
    // An absolute accuracy finer than doubles resolve at this size is answered, not looped on.
    const double fine = editor.document()->curve(0).length(1e-300);
    QVERIFY(std::abs(fine - parabola) <= 1e-9 * 2.9 * scale);
    QVERIFY(std::abs(editor.document()->curve(0).length() - parabola) <= 1e-9 * 2.9 * scale + 1e-9);
}

QTEST_GUILESS_MAIN(TestNumbers)
#include "tst_numbers.moc"
