// The DXF writer's insides (see dxf.h), shared by its parts and by nothing else: the group writer
// and the entities (dxfwrite.cpp), the layers' names, code pages and colours (dxfwritelayers.cpp), the
// drawing's fixed structure (dxfwritetables.cpp) and the ASTM D6673 (AAMA) pieces (dxfwriteaama.cpp).
#pragma once

#include "io/dxf.h"
#include "io/fileio.h"

#include <QByteArray>
#include <QString>

#include <span>
#include <utility>
#include <vector>

namespace kontur::io::dxfwrite {

// The handles of the drawing's fixed structure (the numbers AutoCAD gives a new drawing's); layers
// and entities take theirs from FirstFree on, and $HANDSEED is the next one after them.
enum Handle : unsigned {
    BlockRecordTable = 0x1,
    LayerTable = 0x2,
    StyleTable = 0x3,
    LtypeTable = 0x5,
    ViewTable = 0x6,
    UcsTable = 0x7,
    VportTable = 0x8,
    AppidTable = 0x9,
    DimstyleTable = 0xA,
    RootDictionary = 0xC,
    GroupDictionary = 0xD,
    Layer0 = 0x10,
    StandardStyle = 0x11,
    AcadAppid = 0x12,
    ByBlockLtype = 0x14,
    ByLayerLtype = 0x15,
    ContinuousLtype = 0x16,
    LayoutDictionary = 0x1A,
    PaperSpaceRecord = 0x1B,
    PaperSpaceBlock = 0x1C,
    PaperSpaceEnd = 0x1D,
    PaperLayout = 0x1E,
    ModelSpaceRecord = 0x1F,
    ModelSpaceBlock = 0x20,
    ModelSpaceEnd = 0x21,
    ModelLayout = 0x22,
    StandardDimstyle = 0x27,
    ActiveVport = 0x29,
    FirstFree = 0x100,
};

struct Writer
{
    QByteArray out;
    unsigned handle = FirstFree;       // the next entity's handle (group 5)
    unsigned owner = ModelSpaceRecord; // the block record the entities written next belong to
    QByteArray layer = "0";            // the layer (group 8) and true colour (420, none if negative) of
    int rgb = -1;                      // the entities written next
    qint64 entities = 0;               // as the reader counts them: entities
    qint64 points = 0;                 // and points (vertices, a LINE's two ends, control points)

    void pair(int code, QByteArrayView value)
    {
        out += QByteArray::number(code).rightJustified(3, ' ');
        out += '\n';
        out += value.toByteArray();
        out += '\n';
    }
    void number(int code, double v)
    {
        QByteArray text;
        appendDouble(text, v);
        pair(code, text);
    }
    void integer(int code, long long v) { pair(code, QByteArray::number(v)); }
    void hex(int code, unsigned h) { pair(code, QByteArray::number(h, 16).toUpper()); }
    void point(int code, const geo::Point &p)
    {
        number(code, p.x());
        number(code + 10, p.y());
        number(code + 20, 0.0);
    }
    void point3(int code, double x, double y, double z)
    {
        number(code, x);
        number(code + 10, y);
        number(code + 20, z);
    }
    void entity(const char *type, const char *subclass)
    {
        pair(0, type);
        hex(5, handle++);
        hex(330, owner);
        pair(100, "AcDbEntity");
        pair(8, layer);
        if (rgb >= 0)
            integer(420, rgb);
        pair(100, subclass);
    }
    // A symbol table's head: its name, handle, owner (none) and the number of its records.
    void table(const char *name, unsigned h, int count)
    {
        pair(0, "TABLE");
        pair(2, name);
        hex(5, h);
        pair(330, "0");
        pair(100, "AcDbSymbolTable");
        integer(70, count);
    }
    // A symbol table record up to its name and flags.
    void record(const char *type, unsigned h, unsigned table, const char *subclass, QByteArrayView name,
                int handleCode = 5)
    {
        pair(0, type);
        hex(handleCode, h);
        hex(330, table);
        pair(100, "AcDbSymbolTableRecord");
        pair(100, subclass);
        pair(2, name);
        integer(70, 0);
    }
    // A block's BLOCK entity (its name, no flags, the base point at the origin) on `layer`; in paper
    // space (67) when `paper`.
    void blockBegin(QByteArrayView name, unsigned h, unsigned record, QByteArrayView layer, bool paper = false)
    {
        blockEntity("BLOCK", h, record, layer, paper, "AcDbBlockBegin");
        pair(2, name);
        integer(70, 0);
        point3(10, 0.0, 0.0, 0.0);
        pair(3, name);
        pair(1, "");
    }
    // The ENDBLK that closes it.
    void blockEnd(unsigned h, unsigned record, QByteArrayView layer, bool paper = false)
    {
        blockEntity("ENDBLK", h, record, layer, paper, "AcDbBlockEnd");
    }
    void blockEntity(const char *type, unsigned h, unsigned record, QByteArrayView layer, bool paper,
                     const char *subclass)
    {
        pair(0, type);
        hex(5, h);
        hex(330, record);
        pair(100, "AcDbEntity");
        if (paper)
            integer(67, 1);
        pair(8, layer);
        pair(100, subclass);
    }
    // An object owned by a dictionary, which it names as its reactor too.
    void ownedObject(const char *type, unsigned h, unsigned owner)
    {
        pair(0, type);
        hex(5, h);
        pair(102, "{ACAD_REACTORS");
        hex(330, owner);
        pair(102, "}");
        hex(330, owner);
    }
};

// What $INSUNITS says for Kontur's units, and the factor from document units to the file's.
[[nodiscard]] std::pair<int, double> fileUnits(const QString &units);
// Runs of segments that meet exactly (a curve's segments always do; a gap starts a new entity).
[[nodiscard]] std::vector<std::vector<geo::Bezier>> runsOf(const geo::PiecewiseBezier &curve, double scale);
// Points as one LINE (two, open) or LWPOLYLINE on the writer's layer.
void writeLines(Writer &w, const std::vector<geo::Point> &pts, bool closed);
// A run of segments as one SPLINE (exact), or as lines where it is straight or the options ask for
// polylines (flattened within `tolerance`, in the file's units).
void writeRun(Writer &w, const std::vector<geo::Bezier> &run, bool closed, const DxfExportOptions &options,
              double tolerance);

// The code pages an AC1015 file's text may be in ($DWGCODEPAGE; files of AutoCAD 2007 on are UTF-8):
// Western, Central European (Slovak), Baltic (Latvian), Cyrillic (Bulgarian, Russian).
struct CodePage
{
    const char *dxf;   // $DWGCODEPAGE
    const char *codec; // its name for QStringEncoder
};
// The first code page that has every character of the names (ANSI_1252 for ASCII ones), or
// ANSI_1252 when none has.
[[nodiscard]] const CodePage &codePageFor(const std::vector<QString> &names);
// Text as an AC1015 file holds it: in its code page, a character the page lacks as AutoCAD's escape
// \U+XXXX.
[[nodiscard]] QByteArray dxfText(const QString &text, const CodePage &page);
// A curve's name as a layer name: the characters AutoCAD refuses in symbol table names
// (< > / \ " : ; ? * | = ` ' and control characters) and those beyond the Basic Multilingual Plane
// as "_", no spaces at the ends, at most 255 characters; empty when nothing is left.
[[nodiscard]] QString layerNameOf(const QString &name);
// "#rrggbb" as 0xrrggbb, anything else as -1.
[[nodiscard]] int rgbOf(const QString &color);

struct Layer
{
    QString name;
    int aci = 7;
    QByteArray written; // the name in the file's code page
};

// One layer per distinct name the curves leave (see dxfwritelayers.cpp); the index of each curve's
// layer, -1 for the layer "0".
[[nodiscard]] std::vector<int> layersOf(std::span<const DxfCurve> curves, std::vector<Layer> &layers);

// A block of the drawing besides model and paper space: its record's, BLOCK's and ENDBLK's handles.
struct BlockHandles
{
    QByteArray name;
    unsigned record = 0, begin = 0, end = 0;
};

// HEADER and CLASSES: the version, the code page, the next handle, the units and the extents.
void writeHeader(Writer &w, const CodePage &page, unsigned handseed, int insunits, const geo::Box &extents);
// The nine symbol tables, the layers' records from `firstLayer` on, a BLOCK_RECORD for each of `blocks`.
void writeTables(Writer &w, const std::vector<Layer> &layers, const geo::Box &extents, unsigned firstLayer,
                 const std::vector<BlockHandles> &blocks = {});
// The two blocks every drawing has, model space and paper space, empty (the entities of model space
// are in the ENTITIES section), then `more` (BLOCK … ENDBLK pairs already written).
void writeBlocks(Writer &w, const QByteArray &more = {});
// The whole drawing around the ENTITIES section written in `e` (whose next handle is $HANDSEED): the
// `comment`, HEADER and CLASSES, the tables, the blocks (`blockText` after model and paper space), the
// entities and OBJECTS. `e`'s counts become `entities` and `points`.
[[nodiscard]] QByteArray writeDrawing(const char *comment, const Writer &e, const CodePage &page, int insunits,
                                      const geo::Box &extents, const std::vector<Layer> &layers,
                                      const std::vector<BlockHandles> &blocks, const QByteArray &blockText,
                                      qint64 &entities, qint64 &points);
// The root dictionary with ACAD_GROUP (no groups) and ACAD_LAYOUT (the layouts Model and Layout1,
// whose plot settings plot at 1:1 on no device).
void writeObjects(Writer &w, const geo::Box &extents, bool millimetres);

} // namespace kontur::io::dxfwrite
