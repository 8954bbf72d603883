// OutlineTool: see outlinetool.h.
#include "models/trace/outlinetool.h"

#include "io/records.h"
#include "models/controllers/curvecommands.h"
#include "models/trace/photoimage.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace kontur {

using namespace tracepoints;

OutlineTool::OutlineTool(TraceContext *context, QObject *parent)
    : QObject(parent)
    , m_context(context)
{
}

bool OutlineTool::traceAt(QPointF world)
{
    const cv::Mat *gray = m_context->pictureGrayOrSay();
    EditController *editor = m_context->editor();
    if (!gray || !editor)
        return false;
    const Background bg = editor->document()->background();
    const geo::Point seed = toPoint(world);
    const double mmPerUnit = io::millimetresPerUnit(editor->document()->units());
    // The world's length of a photo pixel at the tap: the scale when there is no unit of length.
    const Eigen::Matrix2d j = bg.imageToWorld().jacobian(bg.worldToImage().map(seed));
    const double unitsPerPhotoPixel = std::sqrt(std::abs(j.determinant()));
    if (!(unitsPerPhotoPixel > 0.0) || !std::isfinite(unitsPerPhotoPixel)) {
        m_context->say(Message::NoPieceFound);
        return false;
    }
    const double pxPerUnit = mmPerUnit > 0.0 ? pxPerMm * mmPerUnit : 2.0 / unitsPerPhotoPixel;
    vision::OutlineOptions options = outlineOptionsIn(mmPerUnit, unitsPerPhotoPixel);
    // A photo pixel's length where the piece lies: the far side of a perspective photo is coarser.
    options.sourcePixel = [toWorld = bg.imageToWorld(), toImage = bg.worldToImage()](const geo::Point &p) {
        return std::sqrt(std::abs(toWorld.jacobian(toImage.map(p)).determinant()));
    };
    if (bg.perspective) // the reference sheet is no piece
        options.ignoreRect = geo::Box(geo::Point(bg.rectOrigin.x(), bg.rectOrigin.y() - bg.rectHeight),
                                      geo::Point(bg.rectOrigin.x() + bg.rectWidth, bg.rectOrigin.y()));

    // First the whole picture, coarsely, to find which piece and how large it is; then that piece
    // alone at the full scale.
    const double reach = mmPerUnit > 0.0 ? 1500.0 / mmPerUnit : 6000.0 * unitsPerPhotoPixel;
    const auto all =
        vision::photoExtentInWorld(cv::Size(gray->cols, gray->rows), bg.imageToWorld().matrix(),
                                   geo::Box(seed - geo::Point(reach, reach), seed + geo::Point(reach, reach)));
    if (!all) {
        m_context->say(Message::NoPieceFound);
        return false;
    }
    auto coarse = worldPatch(*gray, bg, all->min(), all->max(), pxPerUnit, 1200);
    if (!coarse) {
        m_context->say(Message::NoPieceFound);
        return false;
    }
    vision::OutlineOptions coarseOptions = options;
    coarseOptions.tolerance = std::max(options.tolerance, 1.0 / coarse->pxPerUnit);
    const auto rough = vision::traceOutlineAt(coarse->image, coarse->mapping, seed, coarseOptions);
    if (!rough) {
        m_context->say(Message::NoPieceFound);
        return false;
    }
    geo::Box box;
    for (const geo::Point &p : rough->control)
        box.extend(p);
    const double margin = std::max(10.0 / coarse->pxPerUnit, mmPerUnit > 0.0 ? 10.0 / mmPerUnit : 0.0);
    box.extend(box.min() - geo::Point(margin, margin));
    box.extend(box.max() + geo::Point(margin, margin));
    box = box.intersection(*all);
    auto fine = worldPatch(*gray, bg, box.min(), box.max(), pxPerUnit, maxSidePx);
    if (!fine) {
        m_context->say(Message::NoPieceFound);
        return false;
    }
    // The seed may lie beside the piece: the rough outline's middle is inside it or near.
    const auto outline =
        vision::traceOutlineAt(fine->image, fine->mapping, box.contains(seed) ? seed : box.center(), options);
    if (!outline) {
        m_context->say(Message::NoPieceFound);
        return false;
    }
    auto curve = curveFromOutline(*outline);
    if (!curve) {
        m_context->say(Message::OutlineNotFitted);
        return false;
    }
    // The marks on the piece (its grainline, notches, drill holes, fold) make it a pattern piece with them,
    // for the user to check in the piece bar.
    vision::MarkOptions markOptions;
    markOptions.millimetre = options.millimetre;
    if (const auto found = vision::findPieceMarks(fine->image, fine->mapping, *outline, markOptions))
        curve->piece = pieceMarksFrom(*found, curve->toPiecewise());
    m_lastKnots = outline->knotCount();
    // The texts keep TraceController's translation context, where the tools' texts are.
    curve->name =
        //: Automatic name of a curve traced along a piece's outline in the photo: %1 is a running number.
        QCoreApplication::translate("kontur::TraceController", "Outline %1").arg(editor->document()->curveCount() + 1);
    const QString name = curve->name;
    editor->commands()->appendCurve(std::move(*curve),
                                    QCoreApplication::translate("kontur::TraceController", "Trace outline"));
    m_context->say(Message::None);
    if (const auto &piece = editor->document()->curve(editor->document()->curveCount() - 1).piece)
        editor->showMessage(Message::OutlineTracedWithMarks,
                            {name, m_lastKnots, piece->grainline.has_value(), static_cast<int>(piece->notches.size()),
                             static_cast<int>(piece->drillHoles.size()), piece->fold.has_value()});
    else
        editor->showMessage(Message::OutlineTraced, {name, m_lastKnots});
    Q_EMIT traced();
    return true;
}

} // namespace kontur
