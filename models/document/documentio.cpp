// Curves and records: the mapping between models/ and src/io.
#include "models/document/documentio.h"

#include "io/piece.h"
#include "io/seam.h"
#include "io/shapes.h"

#include <QJsonArray>

#include <limits>

namespace kontur {

namespace {

const char *nodeTypeName(geo::NodeType type)
{
    switch (type) {
    case geo::NodeType::Smooth:
        return "smooth";
    case geo::NodeType::Symmetric:
        return "symmetric";
    case geo::NodeType::Corner:
        return "corner";
    }
    return "smooth";
}

QJsonArray pointsToJson(const std::vector<geo::Point> &points)
{
    QJsonArray array;
    for (const geo::Point &p : points)
        array.append(QJsonArray{p.x(), p.y()});
    return array;
}

} // namespace

std::optional<CurveKind> kindFromId(const QString &id)
{
    return geo::kindFromId(id.toStdString());
}

io::CurveRecord toRecord(const Curve &curve)
{
    io::CurveRecord record;
    record.kind = QString::fromLatin1(kindId(curve.kind()));
    record.name = curve.nameGenerated ? QString() : curve.name;
    record.color = curve.color.name(QColor::HexRgb);
    record.visible = curve.visible;
    record.locked = curve.locked;
    if (traitsOf(curve.kind()).usesParameterization)
        record.parameterization = QString::fromLatin1(geo::nameOf(curve.parameterization()));
    if (curve.kind() == CurveKind::Composite) {
        record.points = curve.definingPoints(); // without the closed curve's repeated first knot
        for (int k = 0; k < curve.composite().knotCount(); ++k)
            record.nodeTypes.push_back(QString::fromLatin1(nodeTypeName(curve.composite().nodeType(k))));
        record.closed = curve.isClosed();
    } else {
        record.points = curve.placedPoints();
        if (!curve.tangentEnds().empty())
            record.settings.insert(QStringLiteral("tangentEnds"), pointsToJson(curve.tangentEnds()));
        if (traitsOf(curve.kind()).takesOrder)
            record.settings.insert(QStringLiteral("order"), curve.order());
    }
    if (curve.piece)
        record.settings.insert(QLatin1String(io::kPieceKey), io::pieceToJson(*curve.piece));
    return record;
}

io::DocumentData toDocumentData(const Document &document)
{
    io::DocumentData data;
    data.units = document.units();
    for (const Curve &curve : document.curves()) {
        data.curves.push_back(toRecord(curve));
        // A seam allowance names its source by index; one whose source is deleted is saved free.
        if (curve.seam)
            if (const int source = document.indexOf(curve.seam->source); source >= 0)
                data.curves.back().settings.insert(QLatin1String(io::kSeamKey),
                                                   io::seamToJson({source, curve.seam->options}));
    }
    const Background &b = document.background();
    if (!b.file.isEmpty()) {
        io::BackgroundRecord record;
        record.file = b.file;
        record.visible = b.visible;
        record.opacity = b.opacity;
        record.originX = b.origin.x();
        record.originY = b.origin.y();
        record.scale = b.scale;
        record.rotation = b.rotation;
        record.calibrated = b.calibrated;
        record.ax = b.calibrationA.x();
        record.ay = b.calibrationA.y();
        record.bx = b.calibrationB.x();
        record.by = b.calibrationB.y();
        record.distance = b.calibrationDistance;
        record.locked = b.locked;
        record.perspective = b.perspective;
        for (int i = 0; i < 4; ++i) {
            record.corners[2 * i] = b.corners[i].x();
            record.corners[2 * i + 1] = b.corners[i].y();
        }
        record.rectWidth = b.rectWidth;
        record.rectHeight = b.rectHeight;
        record.rectX = b.rectOrigin.x();
        record.rectY = b.rectOrigin.y();
        data.background = record;
    }
    return data;
}

geo::Result<Curve> fromRecord(const io::CurveRecord &record)
{
    // The record's parts are read by src/io, the same reading kontur-cli and the exports use.
    const auto toGeo = [](const io::Error &e) {
        return geo::Error{geo::ErrorCode::InvalidArgument, e.message.toStdString()};
    };
    geo::Result<Curve> curve = geo::Error{geo::ErrorCode::InvalidArgument, ""};
    if (record.kind == QLatin1String(kindId(CurveKind::Composite))) {
        auto composite = io::compositeCurve(record);
        if (!composite.ok())
            return toGeo(composite.error());
        curve = Curve::makeComposite(std::move(composite.value()));
    } else {
        auto parts = io::curveParts(record);
        if (!parts.ok())
            return toGeo(parts.error());
        curve = Curve::restore(parts->kind, std::move(parts->points), std::move(parts->tangentEnds), parts->order,
                               parts->parameterization);
    }
    if (!curve.ok())
        return curve;
    curve->name = record.name;
    curve->color = QColor(record.color);
    curve->visible = record.visible;
    curve->locked = record.locked;
    if (record.kind == QLatin1String(kindId(CurveKind::Composite)))
        if (const auto seam = io::seamFromSettings(record.settings, std::numeric_limits<int>::max()))
            curve->seam = SeamLink{CurveId::None, seam->options, seam->source};
    curve->piece = io::pieceFromSettings(record.settings);
    return curve;
}

Background fromRecord(const io::BackgroundRecord &record)
{
    Background b;
    b.file = record.file;
    b.visible = record.visible;
    b.opacity = record.opacity;
    b.origin = QPointF(record.originX, record.originY);
    b.scale = record.scale;
    b.rotation = record.rotation;
    b.calibrated = record.calibrated;
    b.calibrationA = QPointF(record.ax, record.ay);
    b.calibrationB = QPointF(record.bx, record.by);
    b.calibrationDistance = record.distance;
    b.locked = record.locked;
    b.perspective = record.perspective;
    for (int i = 0; i < 4; ++i)
        b.corners[i] = QPointF(record.corners[2 * i], record.corners[2 * i + 1]);
    b.rectWidth = record.rectWidth;
    b.rectHeight = record.rectHeight;
    b.rectOrigin = QPointF(record.rectX, record.rectY);
    return b;
}

} // namespace kontur
