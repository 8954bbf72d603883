// Everything the model layer tells the user, as typed ids with arguments (the seed's messages 1–10,
// docs/requirements.md 1.5, and Kontur's own after them): the message line's, the tracing tools',
// the piece bar's, the dialogs' refusals and problems. The UI shows `text`, made in the current
// language when it is read; an object that shows a message holds it in a ShownMessage
// (models/text/shownmessage.h), which announces it again after a language switch.
#pragma once

#include <QObject>
#include <QVariantList>
#include <QtQml/qqmlregistration.h>

#include <utility>

namespace kontur {

class Message
{
    Q_GADGET
    QML_VALUE_TYPE(message)
    Q_PROPERTY(Id id MEMBER id)
    Q_PROPERTY(QVariantList args MEMBER args)
    Q_PROPERTY(bool isEmpty READ isEmpty)
    // The message in the current language, made when read (QML: `message.text`).
    Q_PROPERTY(QString text READ text)
    // Whether the message offers to change the units of files that name none (the banner's button).
    Q_PROPERTY(bool offersUnits READ offersUnits)

public:
    enum Id {
        None = 0,
        FileUploadError = 1,         // seed 1: File upload error!
        TextFileNotCorrect = 2,      // seed 2: .txt file was not correct!
        OutputError = 3,             // seed 3: Output error!
        ConfirmReset = 4,            // seed 4: Do you want to reset this form?
        ControlPointsNotMovable = 5, // seed 5: Not allowed to move control points of <kind> curve! (kind)
        CompositeNotByKeyboard = 6,  // seed 6 (Kontur allows typed handle coordinates; kept for files)
        NoParameterization = 7,      // seed 7: <kind> curves do not use parametrization! (kind)
        TooManyPoints = 8,           // seed 8: Maximum count of input points is <n>! (n)
        TooFewPoints = 9,            // seed 9: <kind> curves can not have less than <n> knot points! (kind, n)
        FillAllValues = 10,          // seed 10: Must fill all values!
        CurveLocked = 11,            // the curve is locked (name)
        FitFailed = 12,              // the knots do not define the fitted cubic (kind, reason code)
        NotPossibleForKind = 13,     // the action needs another kind of curve (kind)
        FileReadError = 14,          // a file could not be read (file name, detail with its place)
        FileWriteError = 15,         // a file could not be written (file name, detail)
        FileImported = 16,           // curves came from a file (count, file name)
        FileSaved = 17,              // the document was saved (file name)
        OutOfRange = 18,             // a typed number or an edit's result beyond the largest double
        KnotOnFirstKnot = 19,        // a knot typed at the end of a closed curve on its first knot
        SeamAllowanceFollows = 20,   // a seam allowance's own points do not move while it is linked
        SeamAllowanceFailed = 21,    // no allowance of that width fits the curve on that side
        SeamAllowanceTooWide = 22,   // a width out of all proportion to the curve (ratio)
        SeamAllowanceTooFine = 23,   // the allowance would take more work than its budget
        SeamAllowanceKept = 24,      // an opened allowance's settings give no shape (name, width)
        AutosaveSettingClamped = 25, // the autosave setting was not usable (text given, seconds used)
        BackgroundUnreadable = 26,   // an opened document's background picture is missing or unreadable (file)
        SeamAllowanceBusy = 27,      // a seam allowance is still being computed (one at a time)
        SeamAllowanceCancelled = 28, // the allowance being computed was cancelled; nothing changed
        SeamAllowanceOutdated = 29,  // its curve changed while the allowance was computed; nothing changed
        // curves came from a file that also held what Kontur does not draw (count, file name, the
        // counts of what was skipped in the order of io::SkippedKind)
        FileImportedSkipped = 30,
        NoPieces = 31, // a pattern-piece (AAMA) export of a document without a visible closed curve
        // curves came from a DXF that names no units, read in those remembered for such files (count,
        // file name, the units, the counts of what was skipped or an empty list); the banner offers
        // to change them (offersUnits)
        FileImportedUnitless = 32,
        UnitlessUnitsChanged = 33, // files that name no units are read in other units from now on (units)
        SeamAllowanceAdded = 34,   // a seam allowance was added (curve name, width, its units)
        OutlineTraced = 35,        // a piece's outline was traced and the tool left (curve name, knots)
        // an AAMA export was written, but pieces without a grainline of their own have no grain line in
        // it (file name, the pieces' names joined, their count)
        PiecesWithoutGrainline = 36,
        NoFileName = 37, // a detail: the file dialog gave no file name
        // a piece's outline was traced with the marks found on it, a pattern piece now (curve name, knots,
        // whether a grainline was found, the notches, the drill holes, whether a fold was found)
        OutlineTracedWithMarks = 38,

        // --- the tracing tools (models/trace), shown in the trace bar ---
        ToleranceNotPositive = 100,
        StrokeTooShort,
        StrokeNotFitted,
        NoPicture,
        TapKnot,
        TapCurve,
        TapOtherCurve,
        NoKnots,
        NotComparable,
        NoMarks,
        DistanceNotPositive,
        LockedCalibrate,
        LockedMove,
        UnknownUnit,
        SamePoints,
        CurveNotTurnable, // the curve's name
        NotConvex,
        NoCorners,
        SidesNotPositive,
        PerspectiveSet,
        CornerNotConvex,
        PictureUnreadable,
        NoSheetFound,
        SheetNotFlat,
        SheetProportions, // the proportions seen and the chosen rectangle's (long : short), as numbers
        CornerNotSnapped,
        CalibrationImprecise, // the estimated error in mm, as a number
        NoPieceFound,
        OutlineNotFitted,
        SnapFailed,

        // --- finishing a traced piece (PieceEdits), shown in the simplify dialog ---
        NothingToJoin = 200,
        NotSimpler,
        BadTolerance,
        NotComposite,

        // --- a pattern piece's marks (PieceMarkEdits) and seams (SeamWidths), shown in the piece bar ---
        SelectPiece = 300,
        PieceNotClosed,
        BadQuantity,
        MarkPointsTooClose,
        NoSuchMark,
        NoAllowanceYet,
        NoSeamChosen,
        BadSeamWidth,
        SeamWidthDoesNotFit,

        // --- why the document cannot be printed (PrintController), shown in the print dialog ---
        NothingToPrint = 400,
        TooManyPages, // the most pages a print may have
        CannotPrint,  // a detail (errorDetail) of the pattern PDF's error

        // --- the lessons' plots (models/teaching), shown under their fields ---
        // the function spline's typed input (FunctionSplinePlot)
        FunctionValuesNotNumbers = 500, // the token that is no number
        FunctionValuesCount,            // the most values
        IntervalNotNumbers,             // the token that is no number
        IntervalOrder,
        KnotsNotNumbers, // the token that is no number
        KnotsCountBells, // the number of knots wanted
        KnotsCount,      // the number of knots wanted
        KnotsOrder,
        DerivativesNotNumbers, // the token that is no number
        DerivativesPerKnot,    // the number of derivatives wanted
        DerivativesTwo,
        // why the cubic segments' practicum draws nothing (PracticumPlot)
        SegmentSameX,
        GuideVertical,
        SegmentDegenerate,
        SplineDegenerate,
    };
    Q_ENUM(Id)

    Message() = default;
    Message(Id messageId, QVariantList arguments = {})
        : id(messageId)
        , args(std::move(arguments))
    {
    }

    Id id = None;
    QVariantList args;

    [[nodiscard]] bool isEmpty() const { return id == None; }
    [[nodiscard]] bool offersUnits() const { return id == FileImportedUnitless; }
    // The message in the current language.
    [[nodiscard]] QString text() const;

    friend bool operator==(const Message &, const Message &) = default;
};

} // namespace kontur
