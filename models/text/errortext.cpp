// Error details by code, translated when shown.
#include "models/text/errortext.h"

#include "io/limits.h"
#include "models/text/messages.h"
#include "text/numbertext.h"

#include <QCoreApplication>
#include <QStringList>

namespace kontur {

namespace {

const QString kIo = QStringLiteral("io");
const QString kGeo = QStringLiteral("geo");
const QString kLine = QStringLiteral("line");
const QString kColumn = QStringLiteral("column");
const QString kPath = QStringLiteral("path");
const QString kCurve = QStringLiteral("curve");
const QString kSkipped = QStringLiteral("skipped");

// A count or a line number, grouped in the UI language (1 000), by the one formatter.
QString count(qint64 n)
{
    return fixedNumber(static_cast<double>(n), 0);
}

QString ioText(io::ErrorCode code)
{
    using C = io::ErrorCode;
    const io::Limits limits;
    switch (code) {
    case C::CannotOpen:
        return QCoreApplication::translate("errors", "the file does not exist or cannot be read.");
    case C::CannotWrite:
        return QCoreApplication::translate(
            "errors", "the file cannot be written there (a folder that is missing or read-only, or a full disk).");
    case C::FileTooLarge:
        //: %1 is a size in megabytes, e.g. "1 000".
        return QCoreApplication::translate("errors", "the file is larger than Kontur reads (%1 MB).")
            .arg(count(limits.maxFileBytes / (1024 * 1024)));
    case C::TooManyPoints:
        //: %1 is a large number of points, e.g. "6 000 000".
        return QCoreApplication::translate("errors", "the file holds more points than Kontur reads (%1).")
            .arg(count(limits.maxPoints));
    case C::TooManyCurves:
        return QCoreApplication::translate("errors", "the file holds more curves than Kontur reads (%1).")
            .arg(count(limits.maxCurves));
    case C::TooDeep:
        //: The file's elements (JSON or XML) are nested inside each other deeper than %1 levels.
        return QCoreApplication::translate("errors", "the file's structure is nested deeper than %1 levels.")
            .arg(count(limits.maxDepth));
    case C::NotUtf8:
        //: UTF-8 is the name of a text encoding; keep it as it is.
        return QCoreApplication::translate("errors", "the file is not text in UTF-8.");
    case C::ExpectedNumber:
        return QCoreApplication::translate("errors", "a number was expected here.");
    case C::NumberOutOfRange:
        return QCoreApplication::translate("errors", "this number is too large for Kontur, or is not a number.");
    case C::TrailingText:
        //: Shown for "1,5 2,5" in a file: files write numbers with a decimal point.
        return QCoreApplication::translate(
            "errors", "more than a point on this line; in files, numbers are written with a decimal point.");
    case C::UnknownDirective:
        return QCoreApplication::translate("errors", "a word Kontur does not know at the start of this line.");
    case C::MissingValue:
        return QCoreApplication::translate("errors", "this line names a setting but gives no value.");
    case C::UnterminatedString:
        return QCoreApplication::translate("errors", "a text in quotation marks is not closed.");
    case C::EmptyRecord:
        return QCoreApplication::translate("errors", "a curve without points.");
    case C::NoPoints:
        return QCoreApplication::translate("errors", "the file holds no points.");
    case C::MissingHeader:
        //: "x,y" is the first line of the file as it must be written; keep it as it is.
        return QCoreApplication::translate("errors", "the first row must be the header “x,y”.");
    case C::WrongFieldCount:
        return QCoreApplication::translate("errors", "each row must hold exactly two values, x and y.");
    case C::UnknownKind:
        return QCoreApplication::translate("errors", "a kind of curve this version of Kontur does not know.");
    case C::UnknownParameterization:
        return QCoreApplication::translate("errors", "a parameterization this version of Kontur does not know.");
    case C::UnknownNodeType:
        return QCoreApplication::translate("errors", "a kind of knot this version of Kontur does not know.");
    case C::UnknownPointKind:
        return QCoreApplication::translate("errors", "the points must be knots or control points.");
    case C::WrongPointCount:
        return QCoreApplication::translate("errors", "too few or too many points for this kind of curve.");
    case C::WrongPointKind:
        return QCoreApplication::translate(
            "errors", "these points do not suit this kind of curve (knots where control points belong, or the "
                      "reverse).");
    case C::InvalidValue:
        return QCoreApplication::translate("errors", "a value outside its range.");
    case C::JsonSyntax:
        return QCoreApplication::translate("errors", "the document is damaged: it is not well-formed JSON.");
    case C::NotKontur:
        return QCoreApplication::translate("errors", "this is not a Kontur document.");
    case C::UnsupportedVersion:
        return QCoreApplication::translate("errors", "the document was written by a newer version of Kontur.");
    case C::MissingField:
        return QCoreApplication::translate("errors", "a value the document needs is missing.");
    case C::WrongType:
        return QCoreApplication::translate(
            "errors", "a value of the wrong type (a number, a text or a list where another belongs).");
    case C::XmlSyntax:
        return QCoreApplication::translate("errors", "the file is damaged: it is not well-formed XML.");
    case C::NotSvg:
        return QCoreApplication::translate("errors", "this is not an SVG drawing.");
    case C::PathSyntax:
        return QCoreApplication::translate("errors", "the outline of a shape (its path data) is malformed.");
    case C::TransformSyntax:
        return QCoreApplication::translate("errors", "a transformation of a shape is malformed.");
    case C::NoPaths:
        return QCoreApplication::translate("errors", "the drawing holds no shapes Kontur can draw.");
    case C::NotKonturPdf:
        return QCoreApplication::translate(
            "errors", "this PDF was not printed by Kontur, so it holds no drawing Kontur can open. Open the .kontur "
                      "document it came from.");
    case C::DxfSyntax:
        return QCoreApplication::translate("errors", "the DXF file is damaged or cut short.");
    case C::DxfUnsupported:
        return QCoreApplication::translate(
            "errors", "the DXF file holds something Kontur cannot read (a binary DXF, or a shape off the drawing "
                      "plane).");
    case C::UnsupportedKind:
        return QCoreApplication::translate("errors", "this kind of curve cannot be written in this format.");
    case C::GeometryError:
        return QCoreApplication::translate(
            "errors", "the points do not define a curve (two knots at the same place, or too few different knots).");
    }
    return QCoreApplication::translate("errors", "a value outside its range.");
}

QString geoText(geo::ErrorCode code)
{
    using C = geo::ErrorCode;
    switch (code) {
    case C::TooFewPoints:
        //: Why a curve in a file was refused, shown after “curve 3: ”.
        return QCoreApplication::translate("errors", "too few points for this kind of curve.");
    case C::AllPointsEqual:
        //: Why a curve in a file was refused, shown after “curve 3: ”.
        return QCoreApplication::translate("errors", "all its points are at the same place.");
    case C::CoincidentPoints:
        //: Why a curve in a file was refused, shown after “curve 3: ”.
        return QCoreApplication::translate("errors", "two consecutive knots are at the same place.");
    case C::TooFewDistinctParameters:
        //: Why a curve in a file was refused, shown after “curve 3: ”.
        return QCoreApplication::translate("errors", "its knots need at least 4 different positions.");
    case C::IllConditioned:
        //: Why a curve in a file was refused, shown after “curve 3: ”.
        return QCoreApplication::translate("errors", "its knots lie too close together to define a curve.");
    case C::NonFiniteInput:
        //: Why a curve in a file was refused, shown after “curve 3: ”.
        return QCoreApplication::translate("errors", "a coordinate is too large for Kontur, or is not a number.");
    case C::IndexOutOfRange:
    case C::InvalidArgument:
        //: Why a curve in a file was refused, shown after “curve 3: ”.
        return QCoreApplication::translate("errors", "its values do not define a curve of its kind.");
    case C::OutOfProportion:
        //: Why a curve in a file was refused, shown after “curve 3: ”.
        return QCoreApplication::translate("errors", "a value out of all proportion to the curve's size.");
    case C::WorkBudget:
        //: Why a curve in a file was refused, shown after “curve 3: ”.
        return QCoreApplication::translate("errors", "it would take more work than Kontur allows for one curve.");
    case C::Cancelled:
        //: Why a curve in a file was refused, shown after “curve 3: ”.
        return QCoreApplication::translate("errors", "the work was cancelled.");
    }
    //: Why a curve in a file was refused, shown after “curve 3: ”.
    return QCoreApplication::translate("errors", "its values do not define a curve of its kind.");
}

} // namespace

QString skippedList(const QVariantList &counts)
{
    QStringList parts;
    for (int k = 0; k < counts.size(); ++k) {
        // A plain variable as the count: Qt 6.4's lupdate loops on a call with a number in it.
        const int n = counts[k].toInt();
        if (n <= 0)
            continue;
        // A count past the kinds io knows (a longer list from elsewhere) is counted as other objects.
        const auto kind =
            k < static_cast<int>(io::kSkippedKinds) ? static_cast<io::SkippedKind>(k) : io::SkippedKind::Other;
        switch (kind) {
        case io::SkippedKind::Text:
            parts << QCoreApplication::translate("messages", "%n text(s)", "", n);
            break;
        case io::SkippedKind::Dimension:
            parts << QCoreApplication::translate("messages", "%n dimension(s)", "", n);
            break;
        case io::SkippedKind::Solid3D:
            parts << QCoreApplication::translate("messages", "%n 3D object(s)", "", n);
            break;
        case io::SkippedKind::Image:
            parts << QCoreApplication::translate("messages", "%n image(s)", "", n);
            break;
        case io::SkippedKind::Spline:
            parts << QCoreApplication::translate("messages", "%n spline(s) given only by fit points or weights", "", n);
            break;
        case io::SkippedKind::Other:
            parts << QCoreApplication::translate("messages", "%n other object(s)", "", n);
            break;
        }
    }
    return parts.join(QStringLiteral(", "));
}

// What a refused drawing held instead, when it held anything.
QString notDrawn(const QVariantList &counts)
{
    const QString skipped = skippedList(counts);
    if (skipped.isEmpty())
        return {};
    //: Appended to the message that curves were read from a file; %1 lists what was not drawn.
    return QCoreApplication::translate("messages", "Not drawn: %1.").arg(skipped);
}

static QVariantMap withSkipped(QVariantMap detail, const io::Error &error)
{
    if (io::anySkipped(error.skipped)) {
        QVariantList skipped;
        for (const int n : error.skipped)
            skipped.append(n);
        detail.insert(kSkipped, skipped);
    }
    return detail;
}

QVariantMap errorDetail(const io::Error &error)
{
    QVariantMap detail{{kIo, static_cast<int>(error.code)}};
    // A drawing or list with nothing to read is the whole file's fault: the place where the reader
    // found out (its end) says nothing.
    if (error.code == io::ErrorCode::NoPaths || error.code == io::ErrorCode::NoPoints)
        return withSkipped(detail, error);
    if (error.line > 0)
        detail.insert(kLine, error.line);
    if (error.column > 0)
        detail.insert(kColumn, error.column);
    if (!error.path.isEmpty())
        detail.insert(kPath, error.path);
    return withSkipped(detail, error);
}

QVariantMap errorDetail(const geo::Error &error, int curve)
{
    QVariantMap detail{{kGeo, static_cast<int>(error.code)}};
    if (curve > 0)
        detail.insert(kCurve, curve);
    return detail;
}

QString detailText(const QVariant &detail)
{
    if (detail.metaType() == QMetaType::fromType<Message>())
        return detail.value<Message>().text();
    if (detail.typeId() != QMetaType::QVariantMap)
        return detail.toString();
    const QVariantMap map = detail.toMap();
    QString what;
    if (map.contains(kIo))
        what = ioText(static_cast<io::ErrorCode>(map.value(kIo).toInt()));
    else if (map.contains(kGeo))
        what = geoText(static_cast<geo::ErrorCode>(map.value(kGeo).toInt()));
    if (const QString skipped = notDrawn(map.value(kSkipped).toList()); !skipped.isEmpty())
        what += QLatin1Char(' ') + skipped;
    const int line = map.value(kLine).toInt();
    const int column = map.value(kColumn).toInt();
    if (line > 0 && column > 0)
        //: Where in a file: %1 the line, %2 the column (character) in it, %3 what is wrong there.
        return QCoreApplication::translate("errors", "line %1, column %2: %3").arg(count(line), count(column), what);
    if (line > 0)
        //: Where in a file: %1 the line, %2 what is wrong there.
        return QCoreApplication::translate("errors", "line %1: %2").arg(count(line), what);
    if (map.contains(kPath))
        //: Where in a document: %1 is the place as the file writes it (e.g. curves[3].points[7]), %2 what is wrong.
        return QCoreApplication::translate("errors", "at %1: %2").arg(map.value(kPath).toString(), what);
    if (map.value(kCurve).toInt() > 0)
        //: %1 is the curve's number in the file (1, 2, …), %2 what is wrong with it.
        return QCoreApplication::translate("errors", "curve %1: %2").arg(count(map.value(kCurve).toInt()), what);
    return what;
}

} // namespace kontur
