// Tests name curves by row (the n-th curve they made); the editing API names them by id. These
// take the id from the document, so a test never computes an id itself; and points as the rows of
// [x, y] that typed coordinates come in.
#pragma once

#include "models/controllers/editcontroller.h"
#include "models/document/document.h"
#include "models/document/enums.h"

#include <QVariantList>

#include <initializer_list>
#include <utility>

namespace kontur::test {

// The id of the curve at `row` of the editor's document (CurveId::None for none).
inline CurveId curveIdAt(const EditController &editor, int row)
{
    return editor.document()->idAt(row);
}

// The same as an int, as CurveCommands and QML take it (0: none).
inline int idAt(const EditController &editor, int row)
{
    return static_cast<int>(editor.document()->idAt(row));
}

// The row of the selected curve (-1: none), as the old selectedCurve() answered.
inline int selectedRow(const EditController &editor)
{
    return editor.selection()->curveRow();
}

// Selects the curve at `row` (and one of its point rows).
inline void selectAt(EditController &editor, int row, int point = -1)
{
    editor.selection()->select(editor.document()->idAt(row), point);
}

// Typed coordinates as QML passes them: a list of [x, y].
inline QVariantList rows(std::initializer_list<std::pair<double, double>> points)
{
    QVariantList out;
    for (const auto &[x, y] : points)
        out << QVariant(QVariantList{x, y});
    return out;
}

// Points as the rows of [x, y] that Placement::createFromCoordinates and the table take.
inline QVariantList rowsOf(const std::vector<geo::Point> &points)
{
    QVariantList rows;
    rows.reserve(static_cast<qsizetype>(points.size()));
    for (const geo::Point &p : points)
        rows << QVariant(QVariantList{p.x(), p.y()});
    return rows;
}

} // namespace kontur::test
