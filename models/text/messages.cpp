// Message texts (translated when shown).
#include "models/text/messages.h"

#include "models/document/curve.h"
#include "models/text/errortext.h"
#include "models/text/numbers.h"
#include "models/text/units.h"

#include <QCoreApplication>
#include <QStringList>

#include <limits>

namespace kontur {

namespace {

QString kindArg(const QVariantList &args, int i)
{
    return i < args.size() ? kindName(static_cast<CurveKind>(args[i].toInt())) : QString();
}

QString numberArg(const QVariantList &args, int i)
{
    return i < args.size() ? fixedNumber(static_cast<double>(args[i].toLongLong()), 0) : QString();
}

// A detail as a sentence, ending in a full stop (the system's reasons come without one).
QString sentence(const QString &text)
{
    if (text.isEmpty() || text.endsWith(QLatin1Char('.')) || text.endsWith(QLatin1Char('?')) ||
        text.endsWith(QLatin1Char('!')))
        return text;
    return text + QLatin1Char('.');
}

} // namespace

QString Message::text() const
{
    switch (id) {
    case None:
        return {};
    case FileUploadError:
        //: %1 is a file name. The background picture could not be loaded.
        return QCoreApplication::translate("messages", "The picture “%1” could not be loaded: the file is missing or "
                                                       "is not a picture Kontur can read.")
            .arg(args.value(0).toString());
    case TextFileNotCorrect:
        return QCoreApplication::translate("messages", "The .txt file is not in the expected format: one “x y” pair "
                                                       "per line.");
    case OutputError:
        //: %1 is a file name, %2 the reason (from the system). The curve's points are appended to a .txt file.
        return QCoreApplication::translate("messages", "Could not append to “%1”: %2")
            .arg(args.value(0).toString(), detailText(args.value(1)));
    case ConfirmReset:
        return QCoreApplication::translate("messages", "Do you want to reset everything? All curves will be removed.");
    case ControlPointsNotMovable:
        //: %1 is the name of a curve kind, as in the kind menu ("Natural spline", "Composite curve").
        return QCoreApplication::translate("messages",
                                           "The control points of curves of the kind “%1” cannot be moved: move the "
                                           "knots.")
            .arg(kindArg(args, 0));
    case CompositeNotByKeyboard:
        return QCoreApplication::translate("messages",
                                           "The control points of a composite curve cannot be moved by keyboard: "
                                           "drag them.");
    case NoParameterization:
        //: %1 is the name of a curve kind, as in the kind menu ("Bézier curve", "Natural spline").
        return QCoreApplication::translate("messages", "Curves of the kind “%1” do not use a parameterization.")
            .arg(kindArg(args, 0));
    case TooManyPoints:
        //: %1 is the largest number of points a curve of this kind can have (for example 1 000).
        return QCoreApplication::translate("messages", "Too many points: a curve of this kind can have at most %1.")
            .arg(numberArg(args, 0));
    case TooFewPoints:
        //: %1 is the name of a curve kind, as in the kind menu ("Bézier curve"); %2 is a small number (2 to 4).
        return QCoreApplication::translate("messages", "A curve of the kind “%1” needs at least %2 points.")
            .arg(kindArg(args, 0), numberArg(args, 1));
    case FillAllValues:
        return QCoreApplication::translate("messages", "Some values are missing or are not numbers: fill in every "
                                                       "field with a number.");
    case CurveLocked:
        return QCoreApplication::translate("messages", "“%1” is locked: unlock it to change it.")
            .arg(args.value(0).toString());
    case FitFailed:
        //: %1 is the name of a curve kind, as in the kind menu ("Least-squares cubic").
        return QCoreApplication::translate("messages",
                                           "The knots of this curve (kind “%1”) do not define a curve: they need at "
                                           "least 4 different positions.")
            .arg(kindArg(args, 0));
    case FileReadError:
        return QCoreApplication::translate("messages", "Could not read “%1”: %2")
            .arg(args.value(0).toString(), detailText(args.value(1)));
    case FileWriteError:
        return QCoreApplication::translate("messages", "Could not write “%1”: %2 The file was left as it was.")
            .arg(args.value(0).toString(), sentence(detailText(args.value(1))));
    case FileImported: {
        // A plain variable as the count: Qt 6.4's lupdate loops on a call with a number in it there.
        const int count = args.value(0).toInt();
        return QCoreApplication::translate("messages", "%n curve(s) read from “%1”.", "", count)
            .arg(args.value(1).toString());
    }
    case FileImportedSkipped: {
        const int count = args.value(0).toInt();
        return QCoreApplication::translate("messages", "%n curve(s) read from “%1”; not drawn: %2.", "", count)
            .arg(args.value(1).toString(), skippedList(args.value(2).toList()));
    }
    case FileImportedUnitless: {
        const int count = args.value(0).toInt();
        //: %1 is a file name, %2 a unit (mm, cm, in or px) the user chose once for DXF files without units.
        QString text = QCoreApplication::translate("messages",
                                                   "%n curve(s) read from “%1”, which does not say its units: read "
                                                   "in %2, as chosen for such files.",
                                                   "", count)
                           .arg(args.value(1).toString(), unitName(args.value(2).toString()));
        if (const QString skipped = notDrawn(args.value(3).toList()); !skipped.isEmpty())
            text += QLatin1Char(' ') + skipped;
        return text;
    }
    case UnitlessUnitsChanged:
        //: %1 is a unit (mm, cm, in or px).
        return QCoreApplication::translate("messages", "DXF files that do not say their units are read in %1 from "
                                                       "the next import on.")
            .arg(unitName(args.value(0).toString()));
    case FileSaved:
        return QCoreApplication::translate("messages", "Saved “%1”.").arg(args.value(0).toString());
    case OutOfRange:
        return QCoreApplication::translate("messages",
                                           "Too large: the coordinates would exceed the largest number Kontur "
                                           "can hold (about %1). Nothing was changed.")
            .arg(significantNumber(std::numeric_limits<double>::max(), 2));
    case KnotOnFirstKnot:
        return QCoreApplication::translate("messages", "This knot lies on the first knot of the closed curve, "
                                                       "which joins them already. Nothing was changed.");
    case NotPossibleForKind:
        //: %1 is the name of a curve kind, as in the kind menu ("Bézier curve", "Global B-spline").
        return QCoreApplication::translate("messages", "This is not possible for curves of the kind “%1”.")
            .arg(kindArg(args, 0));
    case SeamAllowanceFollows:
        return QCoreApplication::translate("messages", "This seam allowance follows its curve: change the curve or the "
                                                       "allowance's settings, or detach the allowance to edit it.");
    case SeamAllowanceFailed:
        return QCoreApplication::translate("messages", "No seam allowance of this width fits the curve on that side.");
    case SeamAllowanceTooWide:
        return QCoreApplication::translate("messages", "This width is more than %1 times the size of the curve: no "
                                                       "seam allowance is made of it. Nothing was changed.")
            .arg(numberArg(args, 0));
    case SeamAllowanceTooFine:
        return QCoreApplication::translate("messages", "This seam allowance would need too many pieces at this size. "
                                                       "Nothing was changed.");
    case AutosaveSettingClamped: {
        const int seconds = args.value(1).toInt();
        return QCoreApplication::translate("messages",
                                           "The autosave setting “%1” cannot be used: a recovery copy is "
                                           "saved every %n second(s).",
                                           "", seconds)
            .arg(args.value(0).toString());
    }
    case BackgroundUnreadable:
        return QCoreApplication::translate("messages", "The background image “%1” is missing or cannot be read. "
                                                       "The curves are shown without it.")
            .arg(args.value(0).toString());
    case SeamAllowanceBusy:
        return QCoreApplication::translate("messages", "A seam allowance is still being computed: wait for it or "
                                                       "cancel it first.");
    case SeamAllowanceCancelled:
        return QCoreApplication::translate("messages", "The seam allowance was cancelled. Nothing was changed.");
    case SeamAllowanceOutdated:
        return QCoreApplication::translate("messages", "The curve changed while its seam allowance was computed. "
                                                       "Nothing was changed; add or apply it again.");
    case SeamAllowanceAdded:
        //: %1 is the curve's name, %2 the width with its unit (10.00 mm).
        return QCoreApplication::translate("messages",
                                           "Seam allowance of %2 added to “%1”. To change it, select it and "
                                           "choose Seam allowance again.")
            .arg(args.value(0).toString(), formatLength(args.value(1).toDouble(), args.value(2).toString()));
    case OutlineTraced: {
        const int knots = args.value(1).toInt();
        //: %1 is the new curve's name; Trace outline is the command in the Trace menu.
        return QCoreApplication::translate(
                   "messages", "“%1” traced with %n knot(s). For the next piece, choose Trace outline again.", "",
                   knots)
            .arg(args.value(0).toString());
    }
    case OutlineTracedWithMarks: {
        const int knots = args.value(1).toInt();
        QStringList marks;
        if (args.value(2).toBool())
            //: One of the marks found on a traced pattern piece, listed after the curve's name.
            marks << QCoreApplication::translate("messages", "the grainline");
        if (const int notches = args.value(3).toInt(); notches > 0)
            //: One of the marks found on a traced pattern piece (V or slit cuts in its edge).
            marks << QCoreApplication::translate("messages", "%n notch(es)", "", notches);
        if (const int holes = args.value(4).toInt(); holes > 0)
            //: One of the marks found on a traced pattern piece.
            marks << QCoreApplication::translate("messages", "%n drill hole(s)", "", holes);
        if (args.value(5).toBool())
            //: One of the marks found on a traced pattern piece: the edge laid on the fabric's fold.
            marks << QCoreApplication::translate("messages", "the fold line");
        //: %1 is the new curve's name, %2 the marks found on it ("the grainline, 3 notches, 1 drill hole");
        //: Pattern piece is the command that opens the piece bar; Trace outline the command in the Trace menu.
        return QCoreApplication::translate("messages",
                                           "“%1” traced with %n knot(s) as a pattern piece with %2. Check them "
                                           "under Pattern piece; for the next piece, choose Trace outline again.",
                                           "", knots)
            .arg(args.value(0).toString(), marks.join(QStringLiteral(", ")));
    }
    case SeamAllowanceKept:
        return QCoreApplication::translate("messages", "The seam allowance “%1” keeps the shape it was saved with: "
                                                       "its width %2 gives no allowance of its curve.")
            .arg(args.value(0).toString(), significantNumber(args.value(1).toDouble(), 6));
    case PiecesWithoutGrainline: {
        const int pieces = args.value(2).toInt();
        //: %1 is the file, %2 the pieces' names; the grainline is the pattern piece's straight-of-grain line.
        return QCoreApplication::translate("messages",
                                           "“%1” was written, but %n piece(s) without a grainline have no grain line "
                                           "in it: %2. Marker making cannot lay them on grain; draw each piece's "
                                           "grainline.",
                                           "", pieces)
            .arg(args.value(0).toString(), args.value(1).toString());
    }
    case NoPieces:
        //: AAMA (ASTM D6673) is the DXF that garment pattern software reads; a piece is a garment pattern piece.
        return QCoreApplication::translate("messages", "Nothing was exported: pattern software takes each piece as a "
                                                       "closed curve, and this document has no visible closed curve. "
                                                       "Close the outline of each piece first.");
    case NoFileName:
        return QCoreApplication::translate("kontur", "no file name was given");

    // The tracing tools' texts keep the translation context they were written in (TraceController's),
    // so that the translations stay as they are; so do a piece's edits, marks and seams, and printing,
    // each in the context of the class that said it first.
    case ToleranceNotPositive:
        return QCoreApplication::translate("kontur::TraceController", "The tolerance must be a positive number.");
    case StrokeTooShort:
        return QCoreApplication::translate("kontur::TraceController",
                                           "Draw along the contour with one finger, a stylus or the mouse.");
    case StrokeNotFitted:
        return QCoreApplication::translate("kontur::TraceController", "The stroke could not be fitted.");
    case NoPicture:
        return QCoreApplication::translate("kontur::TraceController", "Load a background picture first.");
    case TapKnot:
        return QCoreApplication::translate("kontur::TraceController", "Tap a knot of the curve.");
    case TapCurve:
        return QCoreApplication::translate("kontur::TraceController", "Tap a curve.");
    case TapOtherCurve:
        return QCoreApplication::translate("kontur::TraceController", "Tap a second, different curve.");
    case NoKnots:
        return QCoreApplication::translate("kontur::TraceController",
                                           "This kind of curve has no knots to measure between.");
    case NotComparable:
        return QCoreApplication::translate("kontur::TraceController", "These curves cannot be compared.");
    case NoMarks:
        return QCoreApplication::translate("kontur::TraceController", "Tap two points on the picture first.");
    case DistanceNotPositive:
        return QCoreApplication::translate("kontur::TraceController",
                                           "Type the real distance between the two points as a positive number.");
    case LockedCalibrate:
        return QCoreApplication::translate("kontur::TraceController",
                                           "The background is locked. Unlock it to calibrate again.");
    case UnknownUnit:
        return QCoreApplication::translate("kontur::TraceController", "Choose mm, cm or in.");
    case SamePoints:
        return QCoreApplication::translate("kontur::TraceController", "The two points must be different.");
    case LockedMove:
        return QCoreApplication::translate("kontur::TraceController",
                                           "The background is locked. Unlock it to move it.");
    case CurveNotTurnable:
        return QCoreApplication::translate("kontur::TraceController",
                                           "Curve \"%1\" cannot be turned; calibrate without aligning.")
            .arg(args.value(0).toString());
    case NotConvex:
        return QCoreApplication::translate(
            "kontur::TraceController",
            "The four points are not the corners of a rectangle seen in the picture. Tap them again.");
    case NoCorners:
        return QCoreApplication::translate("kontur::TraceController", "Tap the four corners of the rectangle first.");
    case SidesNotPositive:
        return QCoreApplication::translate("kontur::TraceController",
                                           "Type the rectangle's width and height as positive numbers.");
    case PerspectiveSet:
        return QCoreApplication::translate(
            "kontur::TraceController",
            "The picture has a perspective calibration. Clear it to calibrate by two points.");
    case CornerNotConvex:
        return QCoreApplication::translate(
            "kontur::TraceController", "There the corners would not make a rectangle; the corner stays where it was.");
    case PictureUnreadable:
        return QCoreApplication::translate("kontur::TraceController", "The background picture cannot be read.");
    case NoSheetFound:
        return QCoreApplication::translate("kontur::TraceController",
                                           "No sheet found in the picture (a white rectangle with four straight, "
                                           "clear edges). Tap its four corners instead.");
    case SheetNotFlat:
        return QCoreApplication::translate("kontur::TraceController",
                                           "The sheet in the picture is not flat: its edges bend. Lay it flat and "
                                           "take the photo again, or tap its four corners.");
    case SheetProportions:
        //: %1 and %2 are proportions, long side to short side, such as 2.35 and 1.41.
        return QCoreApplication::translate("kontur::TraceController",
                                           "The rectangle found is about %1 : 1, the chosen one %2 : 1. Choose the "
                                           "sheet's size, or tap its four corners.")
            .arg(displayNumber(args.value(0).toDouble(), 2), displayNumber(args.value(1).toDouble(), 2));
    case CornerNotSnapped:
        return QCoreApplication::translate("kontur::TraceController",
                                           "No corner found near the mark; it stays where you dropped it.");
    case CalibrationImprecise: {
        const double mm = args.value(0).toDouble();
        return QCoreApplication::translate("kontur::TraceController",
                                           "The calibration may be off by %1 mm at the far side of the picture. "
                                           "Find the sheet again or refine its corners.")
            .arg(displayNumber(mm, mm < 10.0 ? 1 : 0));
    }
    case NoPieceFound:
        return QCoreApplication::translate("kontur::TraceController",
                                           "No pattern piece found there. Tap inside a piece that stands out "
                                           "from the table.");
    case OutlineNotFitted:
        return QCoreApplication::translate("kontur::TraceController", "The outline could not be made into a curve.");
    case SnapFailed:
        return QCoreApplication::translate("kontur::TraceController",
                                           "No edge found along the stroke; it was fitted as drawn.");
    case NothingToJoin:
        return QCoreApplication::translate("kontur::PieceEdits", "There is no other open composite curve to join.");
    case NotSimpler:
        return QCoreApplication::translate("kontur::PieceEdits",
                                           "No curve with fewer knots stays within that tolerance.");
    case BadTolerance:
        return QCoreApplication::translate("kontur::PieceEdits", "Type a tolerance greater than zero.");
    case NotComposite:
        return QCoreApplication::translate("kontur::PieceEdits", "This works on composite curves that are not locked.");
    case SelectPiece:
        return QCoreApplication::translate("kontur::PieceMarkEdits", "Select a pattern piece first.");
    case PieceNotClosed:
        return QCoreApplication::translate("kontur::PieceMarkEdits",
                                           "A pattern piece is a closed curve: close the curve first.");
    case BadQuantity:
        return QCoreApplication::translate("kontur::PieceMarkEdits", "Type how many to cut: a whole number from 1 up.");
    case MarkPointsTooClose:
        return QCoreApplication::translate("kontur::PieceMarkEdits",
                                           "The two points are too close together: tap two points farther apart.");
    case NoSuchMark:
        return QCoreApplication::translate("kontur::PieceMarkEdits", "There is no mark there.");
    case NoAllowanceYet:
        return QCoreApplication::translate("kontur::SeamWidths", "The piece has no seam allowance yet: add one first.");
    case NoSeamChosen:
        return QCoreApplication::translate("kontur::SeamWidths", "Tap a seam of the piece first.");
    case BadSeamWidth:
        return QCoreApplication::translate("kontur::SeamWidths", "Type the seam allowance: a number from 0 up.");
    case SeamWidthDoesNotFit:
        return QCoreApplication::translate("kontur::SeamWidths",
                                           "The seam allowance cannot be that wide on this piece.");
    case NothingToPrint:
        return QCoreApplication::translate("kontur", "Nothing to print: no curve is visible.");
    case TooManyPages:
        return QCoreApplication::translate("kontur",
                                           "The drawing would need more than %1 pages at true size. Check the "
                                           "document's units.")
            .arg(numberArg(args, 0)); // grouped in the UI language: 10 000
    case CannotPrint:
        return QCoreApplication::translate("kontur", "The drawing cannot be printed: %1")
            .arg(detailText(args.value(0)));
    case FunctionValuesNotNumbers:
        return QCoreApplication::translate("kontur::FunctionSplinePlot", "Function values: “%1” is not a number.")
            .arg(args.value(0).toString());
    case FunctionValuesCount:
        return QCoreApplication::translate("kontur::FunctionSplinePlot",
                                           "Function values: give between 2 and %1 numbers.")
            .arg(args.value(0).toInt());
    case IntervalNotNumbers:
        return QCoreApplication::translate("kontur::FunctionSplinePlot", "Interval: “%1” is not a number.")
            .arg(args.value(0).toString());
    case IntervalOrder:
        return QCoreApplication::translate("kontur::FunctionSplinePlot",
                                           "Interval: give two numbers, the smaller first.");
    case KnotsNotNumbers:
        return QCoreApplication::translate("kontur::FunctionSplinePlot", "Knots: “%1” is not a number.")
            .arg(args.value(0).toString());
    case KnotsCountBells: {
        const int count = args.value(0).toInt();
        return QCoreApplication::translate("kontur::FunctionSplinePlot",
                                           "Knots: give %n number(s), four more than the number of values.", "", count);
    }
    case KnotsCount: {
        const int count = args.value(0).toInt();
        return QCoreApplication::translate("kontur::FunctionSplinePlot",
                                           "Knots: give %n number(s), one per function value.", "", count);
    }
    case KnotsOrder:
        return QCoreApplication::translate("kontur::FunctionSplinePlot",
                                           "Knots: each knot must be greater than the one before.");
    case DerivativesNotNumbers:
        return QCoreApplication::translate("kontur::FunctionSplinePlot", "Derivatives: “%1” is not a number.")
            .arg(args.value(0).toString());
    case DerivativesPerKnot: {
        const int count = args.value(0).toInt();
        return QCoreApplication::translate("kontur::FunctionSplinePlot",
                                           "Derivatives: give %n number(s), one per knot.", "", count);
    }
    case DerivativesTwo:
        return QCoreApplication::translate("kontur::FunctionSplinePlot",
                                           "Derivatives: give two numbers, at the first and the last knot.");
    case SegmentSameX:
        return QCoreApplication::translate("kontur::PracticumPlot",
                                           "The end points have the same x: there is no function segment.");
    case GuideVertical:
        return QCoreApplication::translate("kontur::PracticumPlot",
                                           "A vertical guide vector has no slope dy/dx: a function segment needs one.");
    case SegmentDegenerate:
        return QCoreApplication::translate("kontur::PracticumPlot",
                                           "The end points coincide or a guide vector has no length.");
    case SplineDegenerate:
        return QCoreApplication::translate("kontur::PracticumPlot",
                                           "Two neighbouring points coincide or a guide vector has no length.");
    }
    return {}; // not an id (a number from elsewhere cast to one)
}

} // namespace kontur
