// Error codes and their rendering (see error.h).
#include "io/error.h"

namespace kontur::io {

const char *codeName(ErrorCode code)
{
    switch (code) {
    case ErrorCode::CannotOpen:
        return "cannot-open";
    case ErrorCode::CannotWrite:
        return "cannot-write";
    case ErrorCode::FileTooLarge:
        return "file-too-large";
    case ErrorCode::TooManyPoints:
        return "too-many-points";
    case ErrorCode::TooManyCurves:
        return "too-many-curves";
    case ErrorCode::TooDeep:
        return "too-deep";
    case ErrorCode::NotUtf8:
        return "not-utf8";
    case ErrorCode::ExpectedNumber:
        return "expected-number";
    case ErrorCode::NumberOutOfRange:
        return "number-out-of-range";
    case ErrorCode::TrailingText:
        return "trailing-text";
    case ErrorCode::UnknownDirective:
        return "unknown-directive";
    case ErrorCode::MissingValue:
        return "missing-value";
    case ErrorCode::UnterminatedString:
        return "unterminated-string";
    case ErrorCode::EmptyRecord:
        return "empty-record";
    case ErrorCode::NoPoints:
        return "no-points";
    case ErrorCode::MissingHeader:
        return "missing-header";
    case ErrorCode::WrongFieldCount:
        return "wrong-field-count";
    case ErrorCode::UnknownKind:
        return "unknown-kind";
    case ErrorCode::UnknownParameterization:
        return "unknown-parameterization";
    case ErrorCode::UnknownNodeType:
        return "unknown-node-type";
    case ErrorCode::UnknownPointKind:
        return "unknown-point-kind";
    case ErrorCode::WrongPointCount:
        return "wrong-point-count";
    case ErrorCode::WrongPointKind:
        return "wrong-point-kind";
    case ErrorCode::InvalidValue:
        return "invalid-value";
    case ErrorCode::JsonSyntax:
        return "json-syntax";
    case ErrorCode::NotKontur:
        return "not-kontur";
    case ErrorCode::UnsupportedVersion:
        return "unsupported-version";
    case ErrorCode::MissingField:
        return "missing-field";
    case ErrorCode::WrongType:
        return "wrong-type";
    case ErrorCode::XmlSyntax:
        return "xml-syntax";
    case ErrorCode::NotSvg:
        return "not-svg";
    case ErrorCode::PathSyntax:
        return "path-syntax";
    case ErrorCode::TransformSyntax:
        return "transform-syntax";
    case ErrorCode::NoPaths:
        return "no-paths";
    case ErrorCode::NotKonturPdf:
        return "not-kontur-pdf";
    case ErrorCode::DxfSyntax:
        return "dxf-syntax";
    case ErrorCode::DxfUnsupported:
        return "dxf-unsupported";
    case ErrorCode::UnsupportedKind:
        return "unsupported-kind";
    case ErrorCode::GeometryError:
        return "geometry-error";
    }
    return "unknown";
}

QString Error::toString() const
{
    QString where = file;
    if (line > 0) {
        where += QLatin1Char(':') + QString::number(line);
        if (column > 0)
            where += QLatin1Char(':') + QString::number(column);
    }
    if (!path.isEmpty())
        where += (where.isEmpty() ? QString() : QStringLiteral(": ")) + path;
    return where.isEmpty() ? message : where + QStringLiteral(": ") + message;
}

} // namespace kontur::io
