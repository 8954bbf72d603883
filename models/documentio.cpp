// Curves and records: the mapping between models/ and src/io.
#include "models/documentio.h"

#include <QJsonArray>

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

geo::NodeType nodeTypeFrom(const QString &name)
{
    if (name == QLatin1String("symmetric"))
        return geo::NodeType::Symmetric;
    if (name == QLatin1String("corner"))
        return geo::NodeType::Corner;
    return geo::NodeType::Smooth;
}

QJsonArray pointsToJson(const std::vector<geo::Point> &points)
{
    QJsonArray array;
    for (const geo::Point &p : points)
        array.append(QJsonArray{p.x(), p.y()});
    return array;
}

std::vector<geo::Point> pointsFromJson(const QJsonArray &array)
{
    std::vector<geo::Point> points;
    for (const QJsonValue &value : array) {
        const QJsonArray xy = value.toArray();
        points.emplace_back(xy.at(0).toDouble(std::numeric_limits<double>::quiet_NaN()),
                            xy.at(1).toDouble(std::numeric_limits<double>::quiet_NaN()));
    }
    return points;
}

} // namespace

std::optional<CurveKind> kindFromId(const QString &id)
{
    for (int k = 0; k < kKindCount; ++k)
        if (id == QLatin1String(kindId(static_cast<CurveKind>(k))))
            return static_cast<CurveKind>(k);
    return std::nullopt;
}

io::CurveRecord toRecord(const Curve &curve)
{
    io::CurveRecord record;
    record.kind = QString::fromLatin1(kindId(curve.kind()));
    record.name = curve.name;
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
        if (curve.kind() == CurveKind::BSpline)
            record.settings.insert(QStringLiteral("order"), curve.order());
    }
    return record;
}

io::DocumentData toDocumentData(const Document &document)
{
    io::DocumentData data;
    data.units = document.units();
    for (const Curve &curve : document.curves())
        data.curves.push_back(toRecord(curve));
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
        data.background = record;
    }
    return data;
}

geo::Result<Curve> fromRecord(const io::CurveRecord &record)
{
    const std::optional<CurveKind> kind = kindFromId(record.kind);
    if (!kind)
        return geo::Error{geo::ErrorCode::InvalidArgument,
                          "unknown kind of curve \"" + record.kind.toStdString() + "\""};
    geo::Parameterization parameterization = geo::Parameterization::Uniform;
    if (!record.parameterization.isEmpty())
        (void)geo::parseParameterization(record.parameterization.toStdString(), parameterization);

    geo::Result<Curve> curve = geo::Error{geo::ErrorCode::InvalidArgument, ""};
    if (*kind == CurveKind::Composite) {
        std::vector<geo::Point> control = record.points;
        std::vector<geo::NodeType> types;
        for (const QString &name : record.nodeTypes)
            types.push_back(nodeTypeFrom(name));
        if (record.closed && !control.empty())
            control.push_back(control.front()); // the geometry stores the closing knot again
        auto composite = geo::CompositeCurve::fromParts(std::move(control), std::move(types), record.closed);
        if (!composite.ok())
            return composite.error();
        curve = Curve::makeComposite(std::move(composite.value()));
    } else {
        curve = Curve::restore(*kind, record.points,
                               pointsFromJson(record.settings.value(QStringLiteral("tangentEnds")).toArray()),
                               record.settings.value(QStringLiteral("order")).toInt(0), parameterization);
    }
    if (!curve.ok())
        return curve;
    curve->name = record.name;
    curve->color = QColor(record.color);
    curve->visible = record.visible;
    curve->locked = record.locked;
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
    return b;
}

} // namespace kontur
