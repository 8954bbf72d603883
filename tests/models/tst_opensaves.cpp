// Opening a document changes nothing it should not and says what it cannot show: curves without a
// name get one in the view but are saved as they came (open and save is byte-identical), and a
// background picture that is missing or no picture is said on the message line. And a message with
// the right number: closing a composite curve of two knots needs three.
#include "../curveids.h"
#include "../ownfolders.h"
#include "io/document.h"
#include "models/controllers/documentfiles.h"
#include "models/controllers/editcontroller.h"
#include "models/controllers/recovery.h"
#include "models/document/document.h"

#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <QtTest>

using kontur::DocumentFiles;
using kontur::EditController;
using kontur::Message;

namespace {

kontur::io::CurveRecord arch(const QString &name, double shift)
{
    kontur::io::CurveRecord c;
    c.kind = QStringLiteral("bezier");
    c.name = name;
    c.points = {{0.0 + shift, 0.0}, {1.0 + shift, 2.0}, {3.0 + shift, 2.0}, {4.0 + shift, 0.0}};
    return c;
}

QByteArray bytesOf(const QString &path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

} // namespace

class TestOpenSaves final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { QVERIFY(kontur::test::inOwnFolders(kontur::Recovery::recoveryPath())); }
    void unnamedCurvesAreSavedUnnamed();
    void backgroundThatCannotBeShownIsSaid_data();
    void backgroundThatCannotBeShownIsSaid();
    void closingTwoKnotsNeedsThree();
};

void TestOpenSaves::unnamedCurvesAreSavedUnnamed()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("unnamed.kontur"));
    kontur::io::DocumentData data;
    data.curves = {arch(QString(), 0), arch(QStringLiteral("Named"), 10), arch(QString(), 20)};
    QVERIFY(kontur::io::saveDocument(path, data).ok());
    const QByteArray before = bytesOf(path);
    QVERIFY(!before.isEmpty());

    EditController editor;
    DocumentFiles files;
    files.setEditor(&editor);
    QVERIFY(files.open(QUrl::fromLocalFile(path)));
    // Named in the view (the list shows a name for each), the given name kept.
    QCOMPARE(editor.document()->curveCount(), 3);
    QVERIFY(!editor.document()->curve(0).name.isEmpty());
    QCOMPARE(editor.document()->curve(1).name, QStringLiteral("Named"));
    QVERIFY(!editor.document()->curve(2).name.isEmpty());
    QVERIFY(!editor.isModified());
    // Saved without an edit: the very same bytes.
    QVERIFY(files.save());
    QCOMPARE(bytesOf(path), before);
    // A rename is the user's name, and saved.
    QVERIFY(editor.commands()->setCurveName(kontur::test::idAt(editor, 0), QStringLiteral("Front")));
    QVERIFY(files.save());
    const auto reread = kontur::io::openDocument(path);
    QVERIFY(reread.ok());
    QCOMPARE(reread->curves[0].name, QStringLiteral("Front"));
    QCOMPARE(reread->curves[1].name, QStringLiteral("Named"));
    QCOMPARE(reread->curves[2].name, QString());
}

void TestOpenSaves::backgroundThatCannotBeShownIsSaid_data()
{
    QTest::addColumn<QString>("picture");
    QTest::addColumn<QByteArray>("content"); // empty: no file at all; "png": a real picture
    QTest::addColumn<bool>("said");
    QTest::addRow("missing") << "gone.png" << QByteArray() << true;
    QTest::addRow("not a picture") << "notes.png" << QByteArray("these are words, not pixels\n") << true;
    QTest::addRow("a picture") << "photo.png" << QByteArray("png") << false;
}

void TestOpenSaves::backgroundThatCannotBeShownIsSaid()
{
    QFETCH(QString, picture);
    QFETCH(QByteArray, content);
    QFETCH(bool, said);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString picturePath = dir.filePath(picture);
    if (content == "png") {
        QImage image(8, 6, QImage::Format_RGB32);
        image.fill(Qt::white);
        QVERIFY(image.save(picturePath));
    } else if (!content.isEmpty()) {
        QFile file(picturePath);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(content);
    }
    const QString path = dir.filePath(QStringLiteral("traced.kontur"));
    kontur::io::DocumentData data;
    data.curves = {arch(QStringLiteral("Edge"), 0)};
    kontur::io::BackgroundRecord background;
    background.file = picturePath;
    data.background = background;
    QVERIFY(kontur::io::saveDocument(path, data).ok());

    EditController editor;
    DocumentFiles files;
    files.setEditor(&editor);
    QVERIFY(files.open(QUrl::fromLocalFile(path)));
    QCOMPARE(editor.document()->curveCount(), 1);
    // The reference is kept either way (saving keeps it); only its absence is said.
    QCOMPARE(editor.document()->background().file, picturePath);
    QCOMPARE(editor.message().id == Message::BackgroundUnreadable, said);
    if (said)
        QVERIFY2(editor.messageText().contains(picture), qPrintable(editor.messageText()));
}

void TestOpenSaves::closingTwoKnotsNeedsThree()
{
    EditController editor;
    QVERIFY(editor.placement()->createFromCoordinates(static_cast<int>(kontur::CurveKind::Composite),
                                                      QVariantList{QVariantList{0.0, 0.0}, QVariantList{3.0, 0.0}}));
    const int id = kontur::test::idAt(editor, 0);
    QVERIFY(!editor.commands()->closeCurve(id));
    QCOMPARE(editor.message().id, Message::TooFewPoints);
    QCOMPARE(editor.message().args.value(1).toInt(), 3);
    QVERIFY2(editor.messageText().contains(QLatin1String("3")), qPrintable(editor.messageText()));
    QVERIFY(!editor.document()->curve(0).isClosed());
    // With a third knot it closes.
    QVERIFY(editor.placement()->createFromCoordinates(
        static_cast<int>(kontur::CurveKind::Composite),
        QVariantList{QVariantList{0.0, 0.0}, QVariantList{3.0, 0.0}, QVariantList{3.0, 4.0}}));
    QVERIFY(editor.commands()->closeCurve(kontur::test::idAt(editor, 1)));
    QVERIFY(editor.document()->curve(1).isClosed());
}

QTEST_GUILESS_MAIN(TestOpenSaves)
#include "tst_opensaves.moc"
