// Tiling a pattern over pages at true size (issue 22): page counts by hand for A4 and Letter, the
// overlap between neighbours, the automatic orientation, the labels and the refusals.
#include "geometry/tiling.h"

#include <QtTest>

using namespace kontur::geo;

class TstTiling final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void tilesAlong_data()
    {
        QTest::addColumn<double>("length");
        QTest::addColumn<double>("cell");
        QTest::addColumn<double>("overlap");
        QTest::addColumn<long long>("count");
        QTest::addRow("fits") << 100.0 << 190.0 << 10.0 << 1LL;
        QTest::addRow("exactly one") << 190.0 << 190.0 << 10.0 << 1LL;
        // Two pages cover 2·190 − 10 = 370 mm.
        QTest::addRow("just over one") << 190.001 << 190.0 << 10.0 << 2LL;
        QTest::addRow("exactly two") << 370.0 << 190.0 << 10.0 << 2LL;
        QTest::addRow("just over two") << 370.01 << 190.0 << 10.0 << 3LL;
        QTest::addRow("no overlap") << 380.0 << 190.0 << 0.0 << 2LL;
        QTest::addRow("empty") << 0.0 << 190.0 << 10.0 << 1LL;
        // 1200 mm on A4 portrait width: (1200 − 10) / 180 = 6.61 → 7.
        QTest::addRow("120 cm over 190") << 1200.0 << 190.0 << 10.0 << 7LL;
    }
    void tilesAlong()
    {
        QFETCH(double, length);
        QFETCH(double, cell);
        QFETCH(double, overlap);
        QFETCH(long long, count);
        QCOMPARE(kontur::geo::tilesAlong(length, cell, overlap), count);
        // The pages cover the length, and one page fewer would not.
        QVERIFY(count * cell - (count - 1) * overlap >= length - 1e-9);
        if (count > 1)
            QVERIFY((count - 1) * cell - (count - 2) * overlap < length);
    }

    void counts_data()
    {
        QTest::addColumn<double>("width");
        QTest::addColumn<double>("height");
        QTest::addColumn<int>("paper"); // 0 A4, 1 Letter
        QTest::addColumn<int>("orientation");
        QTest::addColumn<bool>("landscape");
        QTest::addColumn<int>("rows");
        QTest::addColumn<int>("columns");
        // 1200 × 800 mm, margin 10, overlap 10. A4 portrait: cells 190 × 277 → columns
        // ceil(1190/180) = 7, rows ceil(790/267) = 3: 21. Landscape: cells 277 × 190 → columns
        // ceil(1190/267) = 5, rows ceil(790/180) = 5: 25. Auto takes portrait.
        QTest::addRow("A4 auto") << 1200.0 << 800.0 << 0 << int(PageOrientation::Auto) << false << 3 << 7;
        QTest::addRow("A4 landscape") << 1200.0 << 800.0 << 0 << int(PageOrientation::Landscape) << true << 5 << 5;
        // Letter 215.9 × 279.4: cells 195.9 × 259.4. Portrait: ceil(1190/185.9) = 7, ceil(790/249.4) = 4: 28.
        // Landscape: ceil(1190/249.4) = 5, ceil(790/185.9) = 5: 25. Auto takes landscape.
        QTest::addRow("Letter auto") << 1200.0 << 800.0 << 1 << int(PageOrientation::Auto) << true << 5 << 5;
        QTest::addRow("Letter portrait") << 1200.0 << 800.0 << 1 << int(PageOrientation::Portrait) << false << 4 << 7;
        // A wide strip: landscape needs 2 pages (ceil(390/267)), portrait 3 (ceil(390/180)).
        QTest::addRow("strip auto") << 400.0 << 100.0 << 0 << int(PageOrientation::Auto) << true << 1 << 2;
        // A tie (one page either way) stays portrait.
        QTest::addRow("tie") << 100.0 << 100.0 << 0 << int(PageOrientation::Auto) << false << 1 << 1;
    }
    void counts()
    {
        QFETCH(double, width);
        QFETCH(double, height);
        QFETCH(int, paper);
        QFETCH(int, orientation);
        QFETCH(bool, landscape);
        QFETCH(int, rows);
        QFETCH(int, columns);
        TilingOptions o;
        o.paper = paper == 0 ? kPaperA4 : kPaperLetter;
        o.orientation = static_cast<PageOrientation>(orientation);
        const auto t = computeTiling(width, height, o);
        QVERIFY(t.ok());
        QCOMPARE(t->landscape, landscape);
        QCOMPARE(t->rows, rows);
        QCOMPARE(t->columns, columns);
        QCOMPARE(t->pageCount(), rows * columns);
        const double shortSide = std::min(o.paper.width, o.paper.height),
                     longSide = std::max(o.paper.width, o.paper.height);
        QCOMPARE(t->pageWidth, landscape ? longSide : shortSide);
        QCOMPARE(t->cellWidth, t->pageWidth - 20.0);
        // The last page reaches past the pattern; every page is inside the page count.
        const TileRect last = t->tile(rows - 1, columns - 1);
        QVERIFY(last.x + last.width >= width);
        QVERIFY(last.y + last.height >= height);
    }

    void overlap()
    {
        TilingOptions o;
        o.overlap = 15.0;
        const auto t = computeTiling(1000.0, 1000.0, o);
        QVERIFY(t.ok());
        // Each page starts `overlap` before its left and upper neighbours end.
        for (int r = 0; r < t->rows; ++r)
            for (int c = 0; c + 1 < t->columns; ++c) {
                const TileRect a = t->tile(r, c), b = t->tile(r, c + 1);
                QCOMPARE(a.x + a.width - b.x, 15.0);
                QCOMPARE(a.y, b.y);
            }
        for (int r = 0; r + 1 < t->rows; ++r) {
            const TileRect a = t->tile(r, 0), b = t->tile(r + 1, 0);
            QCOMPARE(a.y + a.height - b.y, 15.0);
        }
        // A larger overlap never needs fewer pages.
        o.overlap = 40.0;
        const auto more = computeTiling(1000.0, 1000.0, o);
        QVERIFY(more.ok());
        QVERIFY(more->pageCount() >= t->pageCount());
    }

    void labels()
    {
        QCOMPARE(tileLabel(0, 0), std::string("A1"));
        QCOMPARE(tileLabel(1, 2), std::string("B3"));
        QCOMPARE(tileLabel(25, 9), std::string("Z10"));
        QCOMPARE(tileLabel(26, 0), std::string("AA1"));
        QCOMPARE(tileLabel(27, 0), std::string("AB1"));
        QCOMPARE(tileLabel(26 + 26 * 26, 0), std::string("AAA1"));
    }

    void refusals()
    {
        TilingOptions o;
        QVERIFY(!computeTiling(-1.0, 10.0, o).ok());
        QVERIFY(!computeTiling(std::nan(""), 10.0, o).ok());
        QVERIFY(!computeTiling(1e300, 1e300, o).ok()); // beyond maxPages, no overflow
        o.overlap = 95.0;                              // half of A4's printable 190 mm
        QVERIFY(!computeTiling(10.0, 10.0, o).ok());
        o.overlap = 10.0;
        o.margin = 105.0;
        QVERIFY(!computeTiling(10.0, 10.0, o).ok());
        o.margin = 10.0;
        o.maxPages = 20;
        QVERIFY(!computeTiling(1200.0, 800.0, o).ok()); // 21 pages
        o.maxPages = 21;
        QVERIFY(computeTiling(1200.0, 800.0, o).ok());
    }
};

QTEST_GUILESS_MAIN(TstTiling)
#include "tst_tiling.moc"
