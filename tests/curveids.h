// Tests name curves by row (the n-th curve they made); the editing API names them by id. These
// take the id from the document, so a test never computes an id itself.
#pragma once

#include "models/document.h"
#include "models/editcontroller.h"
#include "models/enums.h"

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

} // namespace kontur::test
