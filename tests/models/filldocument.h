// A document with one curve of every kind, some edited, and a background: what the file tests save,
// open, export and recover.
#pragma once

#include "../curveids.h"
#include "models/controllers/editcontroller.h"
#include "models/document/document.h"

#include <QColor>
#include <QtTest>

#include <cmath>
#include <random>
#include <vector>

namespace kontur::test {

// One curve of every kind, some edited, with a background.
inline void fill(EditController &editor)
{
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> jitter(-3.0, 3.0);
    for (int k = 0; k < kontur::kKindCount; ++k) {
        const auto kind = static_cast<CurveKind>(k);
        std::vector<geo::Point> points;
        const int n = kontur::traitsOf(kind).placementCount > 0 ? kontur::traitsOf(kind).placementCount : 6;
        for (int i = 0; i < n; ++i)
            points.emplace_back(20.0 * i + jitter(rng), 10.0 * std::sin(i) + jitter(rng));
        editor.placement()->setParameterization(k % 3);
        QVERIFY2(editor.placement()->createFromCoordinates(k, rowsOf(points)), qPrintable(editor.messageText()));
    }
    // Edits that only the full state captures: node types, a closed composite, a B-spline order,
    // a moved tangent end, style.
    const int composite = static_cast<int>(CurveKind::Composite);
    QVERIFY(editor.commands()->setNodeType(kontur::test::idAt(editor, composite), 2, kontur::NodeTypes::Corner));
    QVERIFY(editor.commands()->closeCurve(kontur::test::idAt(editor, composite)));
    QVERIFY(editor.commands()->setCurveOrder(kontur::test::idAt(editor, static_cast<int>(CurveKind::BSpline)), 3));
    const int hermite = static_cast<int>(CurveKind::HermiteSpline);
    const geo::Point end = editor.document()->curve(hermite).row(8).position;
    QVERIFY(editor.beginDrag(QPointF(end.x(), end.y()), 1e-9));
    editor.dragTo(QPointF(end.x() + 1.25, end.y() - 0.5));
    editor.endDrag();
    QVERIFY(editor.commands()->setCurveColor(kontur::test::idAt(editor, 0), QColor(QStringLiteral("#1f6fd1"))));
    QVERIFY(editor.commands()->setCurveVisible(kontur::test::idAt(editor, 1), false));
    QVERIFY(editor.commands()->setCurveLocked(kontur::test::idAt(editor, 2), true));
    kontur::Background background;
    background.file = QStringLiteral("/tmp/pattern.png");
    background.opacity = 0.5;
    background.origin = QPointF(-300, 200);
    background.scale = 0.25;
    editor.background()->setBackground(background);
}

} // namespace kontur::test
