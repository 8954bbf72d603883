// The checks of the drawing writers (drawnwrite.h).
#include "io/drawnwrite.h"

#include "io/fileio.h"

#include <cmath>

namespace kontur::io {

std::optional<Error> nonFiniteCoordinate(const QString &path, std::span<const DrawnCurve> curves)
{
    for (const DrawnCurve &c : curves)
        for (const geo::Bezier &b : c.curve.segments())
            for (const geo::Point &p : b.controlPoints())
                if (!std::isfinite(p.x()) || !std::isfinite(p.y())) {
                    Error e;
                    e.file = path;
                    e.code = ErrorCode::NumberOutOfRange;
                    e.message =
                        QStringLiteral("the drawing cannot be written: a coordinate of \"%1\" is not a finite number")
                            .arg(c.name);
                    return e;
                }
    return std::nullopt;
}

std::optional<Error> tooMany(const QString &path, DrawnCount counted, qint64 most, ErrorCode code)
{
    if (counted.count <= most)
        return std::nullopt;
    Error e;
    e.file = path;
    e.code = code;
    e.message = QStringLiteral("the drawing cannot be written: %1 %2; a file holds at most %3")
                    .arg(counted.count)
                    .arg(QLatin1String(counted.what))
                    .arg(most);
    return e;
}

Result<Ok> writeDrawing(const QString &path, const QByteArray &bytes, bool nonFinite, DrawnCount items,
                        DrawnCount points, const Limits &limits)
{
    if (nonFinite)
        return NonFiniteWatch::error(path, QStringLiteral("the drawing"));
    if (auto e = tooMany(path, items, limits.maxCurves, ErrorCode::TooManyCurves))
        return *e;
    if (points.count > limits.maxPoints || bytes.size() > limits.maxFileBytes) {
        Error e;
        e.file = path;
        e.code = points.count > limits.maxPoints ? ErrorCode::TooManyPoints : ErrorCode::FileTooLarge;
        e.message = QStringLiteral("the drawing cannot be written: %1 %2 in %3 bytes; a file holds at most %4 "
                                   "%2 in %5 bytes")
                        .arg(points.count)
                        .arg(QLatin1String(points.what))
                        .arg(bytes.size())
                        .arg(limits.maxPoints)
                        .arg(limits.maxFileBytes);
        return e;
    }
    return writeFileAtomically(path, bytes);
}

} // namespace kontur::io
