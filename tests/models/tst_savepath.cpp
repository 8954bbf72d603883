// Where saves and exports go (models/controllers/savepath.h, and the file dialog's paths in filepaths.h): a save
// dialog's answer as a local path whatever form it takes (a file: URL, Qt 6.4's scheme-less URL of folder and typed
// name, an absolute path or a file: URL typed after the folder, a relative path), the format's extension appended when
// missing or wrong, and the name a save dialog suggests; then DocumentFiles and Exporter writing exactly there.
#include "../ownfolders.h"
#include "io/dxf.h"
#include "models/controllers/documentfiles.h"
#include "models/controllers/editcontroller.h"
#include "models/controllers/exporter.h"
#include "models/controllers/filepaths.h"
#include "models/controllers/recovery.h"
#include "models/controllers/savepath.h"

#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QTemporaryDir>
#include <QtTest>

using kontur::DocumentFiles;
using kontur::Exporter;
using kontur::savePathFor;
using kontur::suggestedFileName;

class TestSavePath final : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { QVERIFY(kontur::test::inOwnFolders(kontur::Recovery::recoveryPath())); }
    void savePath_data();
    void savePath();
    void noNameIsNoPath();
    void suggestedName();
    void exportsEnforceTheExtension();
    void suggestionFollowsTheDocument();
    void suggestionFollowsThePhoto();
    void typedPaths_data();
    void typedPaths();
    void filterPatterns_data();
    void filterPatterns();
    void crumbs();
    void fileDialogPaths();
};

void TestSavePath::savePath_data()
{
    QTest::addColumn<QUrl>("answer");
    QTest::addColumn<QString>("extension");
    QTest::addColumn<QString>("expected");
    const QString folder = QStringLiteral("/home/u/docs");
    // What Qt 6.4's non-native dialog answers: QUrl(currentFolder().path() + "/" + typed name).
    const auto typed = [&](const QString &name) { return QUrl(folder + QLatin1Char('/') + name); };
    QTest::addRow("file URL, right extension") << QUrl::fromLocalFile("/no-such-kontur-folder/a.dxf") << "dxf"
                                               << "/no-such-kontur-folder/a.dxf";
    QTest::addRow("file URL text") << QUrl("file:///no-such-kontur-folder/a%20b.dxf") << "dxf"
                                   << "/no-such-kontur-folder/a b.dxf";
    QTest::addRow("capitals kept") << QUrl::fromLocalFile("/no-such-kontur-folder/A.DXF") << "dxf"
                                   << "/no-such-kontur-folder/A.DXF";
    QTest::addRow("missing extension") << QUrl::fromLocalFile("/no-such-kontur-folder/a") << "dxf"
                                       << "/no-such-kontur-folder/a.dxf";
    // A DXF is never written under .svg: the extension is appended, the SVG of that name untouched.
    QTest::addRow("wrong extension") << QUrl::fromLocalFile("/no-such-kontur-folder/a.svg") << "dxf"
                                     << "/no-such-kontur-folder/a.svg.dxf";
    QTest::addRow("wrong extension, kontur") << QUrl::fromLocalFile("/no-such-kontur-folder/a.dxf") << "kontur"
                                             << "/no-such-kontur-folder/a.dxf.kontur";
    QTest::addRow("trailing dot") << QUrl::fromLocalFile("/no-such-kontur-folder/a.") << "svg"
                                  << "/no-such-kontur-folder/a.svg";
    QTest::addRow("dots in the name") << QUrl::fromLocalFile("/no-such-kontur-folder/bodice.v2") << "csv"
                                      << "/no-such-kontur-folder/bodice.v2.csv";
    QTest::addRow("typed name") << typed("a.dxf") << "dxf"
                                << "/home/u/docs/a.dxf";
    QTest::addRow("typed name, no extension") << typed("a") << "svg"
                                              << "/home/u/docs/a.svg";
    // An absolute path typed in the dialog is not joined to its folder (it was: doubled).
    QTest::addRow("typed absolute path") << typed("/no-such-kontur-folder/x.kontur") << "kontur"
                                         << "/no-such-kontur-folder/x.kontur";
    QTest::addRow("typed absolute path, wrong extension") << typed("/no-such-kontur-folder/x.svg") << "dxf"
                                                          << "/no-such-kontur-folder/x.svg.dxf";
    QTest::addRow("typed absolute path with //") << typed("/no-such-kontur-folder//y/x.txt") << "txt"
                                                 << "/no-such-kontur-folder/y/x.txt";
    QTest::addRow("typed file URL") << typed("file:///no-such-kontur-folder/x.dxf") << "dxf"
                                    << "/no-such-kontur-folder/x.dxf";
    QTest::addRow("typed file URL, no extension") << typed("file:///no-such-kontur-folder/x") << "png"
                                                  << "/no-such-kontur-folder/x.png";
    // The dialog in the root folder: "/" + "/" + name.
    QTest::addRow("root folder") << QUrl("//x.dxf") << "dxf"
                                 << "/x.dxf";
    QTest::addRow("root folder, typed absolute") << QUrl("///no-such-kontur-folder/x.dxf") << "dxf"
                                                 << "/no-such-kontur-folder/x.dxf";
    QTest::addRow("typed relative path") << typed("sub/../b.pdf") << "pdf"
                                         << "/home/u/docs/b.pdf";
    // Relative paths from the base folder given.
    QTest::addRow("relative") << QUrl("sub/a.dxf") << "dxf"
                              << "/base/sub/a.dxf";
    QTest::addRow("relative, no extension") << QUrl("a") << "kontur"
                                            << "/base/a.kontur";
    QTest::addRow("relative file URL") << QUrl::fromLocalFile("a.csv") << "csv"
                                       << "/base/a.csv";
}

void TestSavePath::savePath()
{
    QFETCH(QUrl, answer);
    QFETCH(QString, extension);
    QFETCH(QString, expected);
    QCOMPARE(savePathFor(answer, extension, QStringLiteral("/base")), expected);
}

void TestSavePath::noNameIsNoPath()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QCOMPARE(savePathFor(QUrl(), QStringLiteral("dxf")), QString());
    // The dialog's folder with no name typed, or an existing folder chosen.
    QCOMPARE(savePathFor(QUrl(QStringLiteral("/home/u/docs/")), QStringLiteral("dxf")), QString());
    QCOMPARE(savePathFor(QUrl::fromLocalFile(dir.path()), QStringLiteral("dxf")), QString());
    QCOMPARE(savePathFor(QUrl(QStringLiteral("/home/u/docs/...")), QStringLiteral("dxf")), QString());
    // Not a local file.
    QCOMPARE(savePathFor(QUrl(QStringLiteral("https://example.org/a.dxf")), QStringLiteral("dxf")), QString());
}

void TestSavePath::suggestedName()
{
    const QString untitled = QStringLiteral("Nenosaukts");
    QCOMPARE(suggestedFileName(QUrl::fromLocalFile("/p/bodice.kontur"), "dxf", untitled), "bodice.dxf");
    QCOMPARE(suggestedFileName(QUrl::fromLocalFile("/p/my.bodice.kontur"), "svg", untitled), "my.bodice.svg");
    QCOMPARE(suggestedFileName(QUrl::fromLocalFile("/p/bodice.kontur"), "kontur", untitled), "bodice.kontur");
    QCOMPARE(suggestedFileName(QUrl(), "dxf", untitled), "Nenosaukts.dxf");
}

// DocumentFiles and Exporter write where savePathFor says and reports the name it used.
void TestSavePath::exportsEnforceTheExtension()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    kontur::EditController editor;
    DocumentFiles files;
    files.setEditor(&editor);
    Exporter exporter;
    exporter.setEditor(&editor);
    exporter.setFiles(&files);
    QVERIFY(editor.placement()->createFromCoordinates(
        0, QVariantList{QVariantList{0.0, 0.0}, QVariantList{10.0, 20.0}, QVariantList{30.0, 0.0}}));
    const QString svgName = dir.filePath(QStringLiteral("a.svg"));
    QVERIFY(exporter.exportDxf(QUrl::fromLocalFile(svgName), false));
    QVERIFY(!QFileInfo::exists(svgName));
    QVERIFY(QFileInfo::exists(svgName + QStringLiteral(".dxf")));
    QVERIFY(kontur::io::readDxf(svgName + QStringLiteral(".dxf")).ok());
    QVERIFY2(editor.messageText().contains(QStringLiteral("a.svg.dxf")), qPrintable(editor.messageText()));
    // An absolute path typed after the dialog's folder, and a name without extension.
    const QString other = dir.filePath(QStringLiteral("other"));
    QVERIFY(exporter.exportSvg(QUrl(QStringLiteral("/home/u/docs/") + other)));
    QVERIFY(QFileInfo::exists(other + QStringLiteral(".svg")));
    QVERIFY(files.saveAs(QUrl(QStringLiteral("/home/u/docs/file://") + dir.filePath(QStringLiteral("doc.svg")))));
    QVERIFY(QFileInfo::exists(dir.filePath(QStringLiteral("doc.svg.kontur"))));
    QCOMPARE(files.fileUrl(), QUrl::fromLocalFile(dir.filePath(QStringLiteral("doc.svg.kontur"))));
    // No name: nothing written, and said.
    QVERIFY(!exporter.exportCsv(QUrl(QStringLiteral("/home/u/docs/"))));
    QVERIFY2(editor.messageText().contains(QStringLiteral("no file name")), qPrintable(editor.messageText()));
}

void TestSavePath::suggestionFollowsTheDocument()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    kontur::EditController editor;
    DocumentFiles files;
    files.setEditor(&editor);
    Exporter exporter;
    exporter.setEditor(&editor);
    exporter.setFiles(&files);
    // Unsaved: "Untitled" with the format's extension.
    QCOMPARE(files.suggestedFile(QStringLiteral("dxf")).fileName(), QStringLiteral("Untitled.dxf"));
    // Once exported somewhere, the next suggestion is in that folder.
    QVERIFY(exporter.exportSvg(QUrl::fromLocalFile(dir.filePath(QStringLiteral("first.svg")))));
    QCOMPARE(files.suggestedFile(QStringLiteral("svg")),
             QUrl::fromLocalFile(dir.filePath(QStringLiteral("Untitled.svg"))));
    // Saved as bodice.kontur: bodice.dxf beside it.
    QVERIFY(files.saveAs(QUrl::fromLocalFile(dir.filePath(QStringLiteral("bodice.kontur")))));
    QCOMPARE(files.suggestedFile(QStringLiteral("dxf")),
             QUrl::fromLocalFile(dir.filePath(QStringLiteral("bodice.dxf"))));
    QCOMPARE(files.suggestedFile(QStringLiteral("kontur")),
             QUrl::fromLocalFile(dir.filePath(QStringLiteral("bodice.kontur"))));
}

// An unsaved document traced from a photo: its dialogs start in the photo's folder (until a file is
// opened, saved or exported elsewhere) and name what they write after the photo.
void TestSavePath::suggestionFollowsThePhoto()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(QDir(dir.path()).mkpath(QStringLiteral("photos")) && QDir(dir.path()).mkpath(QStringLiteral("out")));
    const QString photos = dir.filePath(QStringLiteral("photos")), out = dir.filePath(QStringLiteral("out"));
    const QString photo = QDir(photos).filePath(QStringLiteral("front.bodice.jpg"));
    QImage image(64, 48, QImage::Format_RGB32);
    image.fill(Qt::white);
    QVERIFY(image.save(photo));
    kontur::EditController editor;
    DocumentFiles files;
    files.setEditor(&editor);
    Exporter exporter;
    exporter.setEditor(&editor);
    exporter.setFiles(&files);
    QVERIFY(editor.background()->load(QUrl::fromLocalFile(photo)));
    QCOMPARE(files.startFolder(), QUrl::fromLocalFile(photos));
    QCOMPARE(files.suggestedFile(QStringLiteral("pdf")),
             QUrl::fromLocalFile(QDir(photos).filePath("front.bodice.pdf")));
    // A picture chosen in its dialog: that folder is the last one used.
    files.rememberFolder(QUrl::fromLocalFile(photo));
    QCOMPARE(files.startFolder(), QUrl::fromLocalFile(photos));
    // Exported elsewhere: the next dialog starts there, still named after the photo.
    QVERIFY(exporter.exportSvg(QUrl::fromLocalFile(QDir(out).filePath(QStringLiteral("first.svg")))));
    QCOMPARE(files.startFolder(), QUrl::fromLocalFile(out));
    QCOMPARE(files.suggestedFile(QStringLiteral("dxf")), QUrl::fromLocalFile(QDir(out).filePath("front.bodice.dxf")));
    // Saved as a document: its own name and folder win.
    QVERIFY(files.saveAs(QUrl::fromLocalFile(QDir(photos).filePath(QStringLiteral("piece.kontur")))));
    QCOMPARE(files.suggestedFile(QStringLiteral("dxf")), QUrl::fromLocalFile(QDir(photos).filePath("piece.dxf")));
}

// A path typed into the file dialog's path field (filepaths.h), shown the folder /home/u/docs.
void TestSavePath::typedPaths_data()
{
    QTest::addColumn<QString>("typed");
    QTest::addColumn<QString>("expected");
    const QString home = QDir::homePath();
    QTest::addRow("absolute") << "/tmp/a"
                              << "/tmp/a";
    QTest::addRow("spaces around") << "  /tmp/a b  "
                                   << "/tmp/a b";
    QTest::addRow("relative") << "sub/x.dxf"
                              << "/home/u/docs/sub/x.dxf";
    QTest::addRow("parent") << "../other"
                            << "/home/u/other";
    QTest::addRow("doubled slashes") << "/tmp//a/"
                                     << "/tmp/a";
    QTest::addRow("file URL") << "file:///tmp/a%20b.pdf"
                              << "/tmp/a b.pdf";
    QTest::addRow("home") << "~" << home;
    QTest::addRow("under home") << "~/x" << QDir(home).filePath(QStringLiteral("x"));
    QTest::addRow("nothing") << "   "
                             << "";
}

void TestSavePath::typedPaths()
{
    QFETCH(QString, typed);
    QFETCH(QString, expected);
    QCOMPARE(kontur::typedPath(typed, QStringLiteral("/home/u/docs")), expected);
}

void TestSavePath::filterPatterns_data()
{
    QTest::addColumn<QString>("filter");
    QTest::addColumn<QStringList>("expected");
    QTest::addRow("one") << "PDF files (*.pdf)" << QStringList{"*.pdf"};
    QTest::addRow("several") << "Images (*.png *.jpg  *.jpeg)" << QStringList{"*.png", "*.jpg", "*.jpeg"};
    QTest::addRow("parentheses in the name") << "Kontur (printed) patterns (*.pdf)" << QStringList{"*.pdf"};
    QTest::addRow("translated, all") << "Visi faili (*)" << QStringList{"*"};
    QTest::addRow("patterns only") << "*.txt *.csv" << QStringList{"*.txt", "*.csv"};
}

void TestSavePath::filterPatterns()
{
    QFETCH(QString, filter);
    QFETCH(QStringList, expected);
    QCOMPARE(kontur::filterPatterns(filter), expected);
}

void TestSavePath::crumbs()
{
    const QList<kontur::Crumb> crumbs = kontur::crumbsOf(QStringLiteral("/home/u/docs"));
    QCOMPARE(crumbs.size(), 4);
    QCOMPARE(crumbs[0].name, QStringLiteral("/"));
    QCOMPARE(crumbs[0].path, QStringLiteral("/"));
    QCOMPARE(crumbs[1].name, QStringLiteral("home"));
    QCOMPARE(crumbs[3].name, QStringLiteral("docs"));
    QCOMPARE(crumbs[3].path, QStringLiteral("/home/u/docs"));
    QCOMPARE(kontur::crumbsOf(QStringLiteral("/")).size(), 1);
}

// What the dialog asks FilePaths on real files: what a typed path names, and the file a save writes.
void TestSavePath::fileDialogPaths()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(QDir(dir.path()).mkpath(QStringLiteral("sub")));
    QFile existing(dir.filePath(QStringLiteral("a.dxf")));
    QVERIFY(existing.open(QIODevice::WriteOnly));
    existing.close();
    const QUrl folder = QUrl::fromLocalFile(dir.path());
    const kontur::FilePaths paths;
    const auto kind = [&](const QString &typed) {
        return static_cast<kontur::FilePaths::Kind>(paths.resolve(typed, folder).value(QStringLiteral("kind")).toInt());
    };
    QCOMPARE(kind(QStringLiteral("sub")), kontur::FilePaths::Kind::Folder);
    QCOMPARE(kind(dir.filePath(QStringLiteral("sub"))), kontur::FilePaths::Kind::Folder);
    QCOMPARE(kind(QStringLiteral("a.dxf")), kontur::FilePaths::Kind::File);
    QCOMPARE(kind(QStringLiteral("new.dxf")), kontur::FilePaths::Kind::NewFile);
    QCOMPARE(kind(QStringLiteral("nowhere/new.dxf")), kontur::FilePaths::Kind::Missing);
    QCOMPARE(kind(QString()), kontur::FilePaths::Kind::Missing);
    const QVariantMap file = paths.resolve(QStringLiteral("a.dxf"), folder);
    QCOMPARE(file.value(QStringLiteral("folder")).toUrl(), folder);
    QCOMPARE(file.value(QStringLiteral("url")).toUrl(), QUrl::fromLocalFile(dir.filePath(QStringLiteral("a.dxf"))));
    // The extension as DocumentFiles appends it; none where the dialog has no suffix.
    QCOMPARE(paths.saveTarget(QStringLiteral("b"), folder, QStringLiteral("dxf")),
             QUrl::fromLocalFile(dir.filePath(QStringLiteral("b.dxf"))));
    QCOMPARE(paths.saveTarget(QStringLiteral("a.svg"), folder, QStringLiteral("dxf")),
             QUrl::fromLocalFile(dir.filePath(QStringLiteral("a.svg.dxf"))));
    QCOMPARE(paths.saveTarget(QStringLiteral("A.DXF"), folder, QStringLiteral("dxf")),
             QUrl::fromLocalFile(dir.filePath(QStringLiteral("A.DXF"))));
    QCOMPARE(paths.saveTarget(QStringLiteral("sub/c"), folder, QString()),
             QUrl::fromLocalFile(dir.filePath(QStringLiteral("sub/c"))));
    QVERIFY(paths.saveTarget(QStringLiteral("sub"), folder, QStringLiteral("dxf")).isEmpty());
    QVERIFY(paths.exists(QUrl::fromLocalFile(dir.filePath(QStringLiteral("a.dxf")))));
    QCOMPARE(paths.parentFolder(QUrl::fromLocalFile(dir.filePath(QStringLiteral("sub")))), folder);
    QVERIFY(paths.parentFolder(QUrl::fromLocalFile(QStringLiteral("/"))).isEmpty());
}

QTEST_GUILESS_MAIN(TestSavePath)
#include "tst_savepath.moc"
