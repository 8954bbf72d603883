// The seam allowance link in documents (see seam.h).
#include "io/seam.h"

#include "io/records.h"

#include <cmath>

namespace kontur::io {

QJsonObject seamToJson(const SeamSettings &seam)
{
    return QJsonObject{
        {QStringLiteral("source"), seam.source},
        {QStringLiteral("distance"), seam.options.distance},
        {QStringLiteral("side"), QLatin1String(geo::offsetSideId(seam.options.side))},
        {QStringLiteral("join"), QLatin1String(geo::offsetJoinId(seam.options.join))},
        {QStringLiteral("miterLimit"), seam.options.miterLimit},
        {QStringLiteral("tolerance"), seam.options.tolerance},
    };
}

std::optional<SeamSettings> seamFromSettings(const QJsonObject &settings, int curveCount)
{
    const QJsonValue value = settings.value(QLatin1String(kSeamKey));
    if (!value.isObject())
        return std::nullopt;
    const QJsonObject o = value.toObject();
    SeamSettings seam;
    const QJsonValue source = o.value(QLatin1String("source"));
    if (!source.isDouble() || source.toDouble() != std::floor(source.toDouble()))
        return std::nullopt;
    seam.source = source.toInt(-1);
    if (seam.source < 0 || seam.source >= curveCount)
        return std::nullopt;
    const auto number = [&](const char *key, double &out) {
        const QJsonValue v = o.value(QLatin1String(key));
        if (!v.isDouble() || !std::isfinite(v.toDouble()))
            return false;
        out = v.toDouble();
        return true;
    };
    if (!number("distance", seam.options.distance) || !(seam.options.distance > 0) ||
        !number("miterLimit", seam.options.miterLimit) || !(seam.options.miterLimit >= 0) ||
        !number("tolerance", seam.options.tolerance) || !(seam.options.tolerance > 0))
        return std::nullopt;
    if (!geo::offsetSideFromId(o.value(QLatin1String("side")).toString().toStdString(), seam.options.side) ||
        !geo::offsetJoinFromId(o.value(QLatin1String("join")).toString().toStdString(), seam.options.join))
        return std::nullopt;
    return seam;
}

double unitsPerCentimetre(const QString &unit)
{
    const double mm = millimetresPerUnit(unit, true);
    return mm > 0.0 ? 10.0 / mm : 0.0;
}

geo::OffsetOptions defaultSeamOptions(const QString &unit)
{
    const double cm = unitsPerCentimetre(unit) > 0 ? unitsPerCentimetre(unit) : 1.0;
    geo::OffsetOptions o;
    o.distance = cm;
    o.tolerance = 0.005 * cm;
    o.miterLimit = 3.0 * cm;
    return o;
}

} // namespace kontur::io
