// Tests of CSV points: header and separators, quoted fields, a malformed-input table with code, line
// and column, and exact round trips.
#include "io/csv.h"
#include "iotestutil.h"

#include <QTemporaryDir>
#include <QTest>

#include <random>

using namespace kontur;
using namespace kontur::io;

class TestCsv final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void valid_data();
    void valid();
    void malformed_data();
    void malformed();
    void roundTrip();
};

void TestCsv::valid_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<int>("count");
    QTest::addColumn<double>("lastY");
    QTest::addRow("plain") << QByteArray("x,y\n0,0\n1,2\n") << 2 << 2.0;
    QTest::addRow("quoted") << QByteArray("\"x\",\"y\"\n\"1.5\",\"-2e3\"\n") << 1 << -2000.0;
    QTest::addRow("spaces crlf") << QByteArray("X , Y\r\n 1 , 2 \r\n\r\n3,4\r\n") << 2 << 4.0;
    QTest::addRow("semicolon") << QByteArray("x;y\n1;2\n") << 1 << 2.0;
    QTest::addRow("tab") << QByteArray("x\ty\n1\t2\n") << 1 << 2.0;
    QTest::addRow("bom, blank first") << QByteArray("\xEF\xBB\xBF\nx,y\n1,7") << 1 << 7.0;
}

void TestCsv::valid()
{
    QFETCH(QByteArray, text);
    QFETCH(int, count);
    QFETCH(double, lastY);
    auto r = parseCsvPoints(text);
    QVERIFY2(r.ok(), qPrintable(r.ok() ? QString() : r.error().toString()));
    QCOMPARE(static_cast<int>(r->size()), count);
    QCOMPARE(r->back().y(), lastY);
}

void TestCsv::malformed_data()
{
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<QString>("code");
    QTest::addColumn<int>("line");
    QTest::addColumn<int>("column");
    QTest::addRow("no header") << QByteArray("1,2\n3,4\n") << "missing-header" << 1 << 1;
    QTest::addRow("empty") << QByteArray("") << "missing-header" << 1 << 0;
    QTest::addRow("header only") << QByteArray("x,y\n") << "no-points" << 1 << 0;
    QTest::addRow("three fields") << QByteArray("x,y\n1,2\n1,2,3\n") << "wrong-field-count" << 3 << 5;
    QTest::addRow("one field") << QByteArray("x,y\n1\n") << "wrong-field-count" << 2 << 2;
    QTest::addRow("decimal comma") << QByteArray("x;y\n1,5;2\n") << "expected-number" << 2 << 1;
    QTest::addRow("text") << QByteArray("x,y\n1, abc\n") << "expected-number" << 2 << 4;
    QTest::addRow("empty field") << QByteArray("x,y\n1,\n") << "expected-number" << 2 << 3;
    QTest::addRow("unterminated") << QByteArray("x,y\n\"1,2\n") << "unterminated-string" << 2 << 1;
    QTest::addRow("out of range") << QByteArray("x,y\n1,-1e400\n") << "number-out-of-range" << 2 << 3;
    QTest::addRow("text after quote") << QByteArray("x,y\n\"1\"x,2\n") << "expected-number" << 2 << 1;
}

void TestCsv::malformed()
{
    QFETCH(QByteArray, text);
    QFETCH(QString, code);
    QFETCH(int, line);
    QFETCH(int, column);
    auto r = parseCsvPoints(text, QStringLiteral("p.csv"));
    QCOMPARE(test::errorPlace(r), test::errorPlace(code, line, column));
}

void TestCsv::roundTrip()
{
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> d(-1e6, 1e6);
    std::vector<geo::Point> pts;
    for (int i = 0; i < 500; ++i)
        pts.emplace_back(d(rng) * std::pow(10.0, i % 40 - 20), d(rng));
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("p.csv"));
    QVERIFY(writeCsvPoints(path, pts).ok());
    auto r = readCsvPoints(path);
    QVERIFY(r.ok());
    QCOMPARE(*r, pts);
    Limits small;
    small.maxPoints = 10;
    r = readCsvPoints(path, small);
    QVERIFY(!r.ok());
    QCOMPARE(r.error().code, ErrorCode::TooManyPoints);
}

QTEST_GUILESS_MAIN(TestCsv)
#include "tst_csv.moc"
