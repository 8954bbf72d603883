// DXF export (see dxf.h): a complete, minimal AutoCAD 2000 (AC1015) drawing as Autodesk's "DXF
// Reference" (AutoCAD 2000) describes it and AutoCAD writes a new one: HEADER (version, code page,
// handle seed, units, extents), an empty CLASSES section, the nine symbol tables (VPORT *Active, the
// line types ByBlock/ByLayer/Continuous, the layers, STYLE and DIMSTYLE Standard, empty VIEW and UCS,
// APPID ACAD, BLOCK_RECORD *Model_Space and *Paper_Space), BLOCKS (their BLOCK/ENDBLK pairs), ENTITIES
// (one SPLINE, LINE or LWPOLYLINE per run of a curve) and OBJECTS (the root dictionary, ACAD_GROUP and
// ACAD_LAYOUT with the layouts Model and Layout1). Every table, record, block, entity and object has
// its handle and its owner (330) and the subclass markers (100) the reference gives it. Curves are on
// layers named after them, one per name; its colour is the entity's true colour (420) and the
// layer's nearest AutoCAD Color Index (62). The ASTM D6673 (AAMA) form adds a block per garment piece
// on the standard's numbered layers. Over 600 lines because the drawing's fixed structure (nine
// tables, two blocks, two layouts with their plot settings) is written group by group, as the reference
// lists the groups, beside the entities, the layer names' code pages and the colour index.
#include "io/dxf.h"

#include "io/fileio.h"
#include "io/seam.h"
#include "io/shapes.h"

#include <QHash>
#include <QSet>
#include <QStringDecoder>
#include <QStringEncoder>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <tuple>

namespace kontur::io {

namespace {

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
std::pair<int, double> fileUnits(const QString &units)
{
    if (units == QLatin1String("mm"))
        return {4, 1.0};
    if (units == QLatin1String("cm"))
        return {5, 1.0};
    if (units == QLatin1String("in"))
        return {1, 1.0};
    if (units == QLatin1String("pt"))
        return {1, 1.0 / 72.0};
    return {0, 1.0};
}

// Runs of segments that meet exactly (a curve's segments always do; a gap starts a new entity).
std::vector<std::vector<geo::Bezier>> runsOf(const geo::PiecewiseBezier &curve, double scale)
{
    std::vector<std::vector<geo::Bezier>> runs;
    for (const geo::Bezier &b : curve.segments()) {
        if (b.isEmpty())
            continue;
        std::vector<geo::Point> pts = b.controlPoints();
        if (scale != 1.0)
            for (geo::Point &p : pts)
                p *= scale;
        if (runs.empty() || runs.back().back().endPoint() != pts.front())
            runs.emplace_back();
        runs.back().emplace_back(std::move(pts));
    }
    return runs;
}

} // namespace

bool isStraight(const geo::Bezier &b)
{
    if (b.degree() <= 1)
        return true;
    const geo::Point a = b.startPoint(), d = b.endPoint() - a;
    const double length2 = d.squaredNorm();
    if (!(length2 > 0) || !std::isfinite(length2))
        return false;
    // What an elevated line's rounding leaves: a few units in the last place of the coordinates.
    const double slack = 1e-12 * (a.norm() + b.endPoint().norm() + std::sqrt(length2));
    for (const geo::Point &p : b.controlPoints()) {
        const geo::Point v = p - a;
        const double t = v.dot(d) / length2;
        const double off = std::abs(v.x() * d.y() - v.y() * d.x()) / std::sqrt(length2);
        if (off > slack || t < 0.0 || t > 1.0)
            return false;
    }
    return true;
}

namespace {

void writeLines(Writer &w, const std::vector<geo::Point> &pts, bool closed)
{
    if (pts.size() == 2 && !closed) {
        w.entity("LINE", "AcDbLine");
        ++w.entities;
        w.points += 2;
        w.point(10, pts[0]);
        w.point(11, pts[1]);
        return;
    }
    w.entity("LWPOLYLINE", "AcDbPolyline");
    ++w.entities;
    w.points += static_cast<qint64>(pts.size());
    w.integer(90, static_cast<long long>(pts.size()));
    w.integer(70, closed ? 1 : 0);
    for (const geo::Point &p : pts) {
        w.number(10, p.x());
        w.number(20, p.y());
    }
}

// A run of segments as one SPLINE: every piece at the run's highest degree p (lower ones elevated,
// the same curve), the knots 0 (p+1 times), 1, 2, … (p times each), n (p+1 times): the Bézier form
// of a B-spline (Piegl & Tiller, "The NURBS Book", 2nd ed., §5.6), so the control points are the
// pieces' own control points, shared ends once.
void writeSpline(Writer &w, const std::vector<geo::Bezier> &run)
{
    int degree = 1;
    for (const geo::Bezier &b : run)
        degree = std::max(degree, b.degree());
    std::vector<geo::Point> control{run.front().startPoint()};
    for (const geo::Bezier &b : run) {
        const geo::Bezier piece = b.degree() < degree ? b.elevated(degree - b.degree()) : b;
        control.insert(control.end(), piece.controlPoints().begin() + 1, piece.controlPoints().end());
    }
    const int pieces = static_cast<int>(run.size());
    w.entity("SPLINE", "AcDbSpline");
    ++w.entities;
    w.points += static_cast<qint64>(control.size());
    w.number(210, 0.0);
    w.number(220, 0.0);
    w.number(230, 1.0);
    w.integer(70, 8); // planar
    w.integer(71, degree);
    w.integer(72, static_cast<long long>(control.size()) + degree + 1);
    w.integer(73, static_cast<long long>(control.size()));
    w.integer(74, 0);
    w.number(42, 1e-10);
    w.number(43, 1e-10);
    for (int i = 0; i <= pieces; ++i) {
        const int times = (i == 0 || i == pieces) ? degree + 1 : degree;
        for (int k = 0; k < times; ++k)
            w.integer(40, i);
    }
    for (const geo::Point &p : control)
        w.point(10, p);
}

void writeRun(Writer &w, const std::vector<geo::Bezier> &run, bool closed, const DxfExportOptions &options,
              double tolerance)
{
    const bool linear = std::all_of(run.begin(), run.end(), [](const geo::Bezier &b) { return isStraight(b); });
    if (linear || options.flavour == DxfFlavour::Polyline) {
        std::vector<geo::Point> pts;
        for (const geo::Bezier &b : run) {
            if (isStraight(b)) {
                if (pts.empty())
                    pts.push_back(b.startPoint());
                pts.push_back(b.endPoint());
            } else {
                geo::flatten(b, tolerance, pts);
            }
        }
        // A closed curve: the polyline's closed flag stands for its last vertex, the first again.
        const bool close = closed && pts.size() >= 3 && pts.back() == pts.front();
        if (close)
            pts.pop_back();
        writeLines(w, pts, close);
        return;
    }
    writeSpline(w, run);
}

} // namespace

double defaultDxfTolerance(const QString &units)
{
    const double mm = 0.05;
    if (units == QLatin1String("cm"))
        return mm / 10;
    if (units == QLatin1String("in"))
        return mm / 25.4;
    if (units == QLatin1String("pt"))
        return mm / 25.4 * 72;
    if (units == QLatin1String("px"))
        return mm / 25.4 * 96;
    return mm;
}

namespace {

// The AutoCAD Color Index's colours (ACI 1 to 255; "DXF Reference", Color Index): 1–9 the named ones,
// 10–249 the colour wheel (24 hues 15° apart; per hue five values 255, 165, 127, 76, 38, each fully and
// half saturated), 250–255 greys. ACI 7 is drawn black on a white background and white on a black one.
std::array<int, 3> aciColour(int aci)
{
    static constexpr std::array<std::array<int, 3>, 10> named{{{0, 0, 0},
                                                               {255, 0, 0},
                                                               {255, 255, 0},
                                                               {0, 255, 0},
                                                               {0, 255, 255},
                                                               {0, 0, 255},
                                                               {255, 0, 255},
                                                               {255, 255, 255},
                                                               {128, 128, 128},
                                                               {192, 192, 192}}};
    if (aci < 10)
        return named[static_cast<std::size_t>(aci)];
    if (aci >= 250) {
        static constexpr std::array<int, 6> greys{51, 80, 105, 130, 190, 255};
        const int g = greys[static_cast<std::size_t>(aci - 250)];
        return {g, g, g};
    }
    static constexpr std::array<double, 5> values{255, 165, 127, 76, 38};
    const int k = aci - 10;
    const double value = values[static_cast<std::size_t>(k % 10 / 2)];
    const bool half = k % 2 == 1;
    // The hue's fully saturated colour (HSV with S = V = 1), each channel in [0, 1].
    const double h = (k / 10) * 15.0 / 60.0;
    const auto channel = [&](double n) {
        const double t = std::fmod(n + h, 6.0);
        return std::clamp(std::min(t, 4.0 - t), 0.0, 1.0);
    };
    std::array<int, 3> rgb{};
    for (int c = 0; c < 3; ++c) {
        const double full = 1.0 - channel(c == 0 ? 5.0 : c == 1 ? 3.0 : 1.0);
        rgb[static_cast<std::size_t>(c)] = static_cast<int>(std::floor(value * (half ? 0.5 + full / 2 : full)));
    }
    return rgb;
}

// The ACI nearest to a colour (squared RGB distance; the lowest index of equals), ACI 7 standing for
// both black and white.
int nearestAci(int rgb)
{
    const int r = (rgb >> 16) & 0xff, g = (rgb >> 8) & 0xff, b = rgb & 0xff;
    const auto distance = [&](const std::array<int, 3> &c) {
        return (c[0] - r) * (c[0] - r) + (c[1] - g) * (c[1] - g) + (c[2] - b) * (c[2] - b);
    };
    static const std::array<std::array<int, 3>, 256> palette = [] {
        std::array<std::array<int, 3>, 256> p{};
        for (int aci = 1; aci <= 255; ++aci)
            p[static_cast<std::size_t>(aci)] = aciColour(aci);
        return p;
    }();
    int best = 7;
    int bestDistance = std::min(distance({0, 0, 0}), distance({255, 255, 255}));
    for (int aci = 1; aci <= 255; ++aci)
        if (const int d = distance(palette[static_cast<std::size_t>(aci)]); d < bestDistance) {
            best = aci;
            bestDistance = d;
        }
    return best;
}

// "#rrggbb" as 0xrrggbb, anything else as -1.
int rgbOf(const QString &color)
{
    if (!isColorName(color))
        return -1;
    return static_cast<int>(QStringView(color).mid(1).toUInt(nullptr, 16));
}

// A curve's name as a layer name: the characters AutoCAD refuses in symbol table names
// (< > / \ " : ; ? * | = ` ' and control characters) and those beyond the Basic Multilingual Plane
// as "_", no spaces at the ends, at most 255 characters; empty when nothing is left.
QString layerNameOf(const QString &name)
{
    static const QString refused = QStringLiteral("<>/\\\":;?*|=`'");
    QString out;
    for (const char32_t c : name.toUcs4()) {
        if (c < 0x20 || c == 0x7f || c > 0xffff || refused.contains(QChar(static_cast<char16_t>(c))))
            out += QLatin1Char('_');
        else
            out += QChar(static_cast<char16_t>(c));
    }
    return out.trimmed().left(255);
}

// The code pages an AC1015 file's text may be in ($DWGCODEPAGE; files of AutoCAD 2007 on are UTF-8):
// Western, Central European (Slovak), Baltic (Latvian), Cyrillic (Bulgarian, Russian).
struct CodePage
{
    const char *dxf;   // $DWGCODEPAGE
    const char *codec; // its name for QStringEncoder
};
constexpr std::array<CodePage, 4> codePages{{{"ANSI_1252", "windows-1252"},
                                             {"ANSI_1250", "windows-1250"},
                                             {"ANSI_1257", "windows-1257"},
                                             {"ANSI_1251", "windows-1251"}}};

bool isAscii(const QString &text)
{
    return std::all_of(text.begin(), text.end(), [](QChar c) { return c.unicode() < 0x80; });
}

// Whether a code page has every character of a text.
bool encodes(const QString &text, const CodePage &page)
{
    if (isAscii(text))
        return true;
    // By the round trip: an encoder may put a substitute for what its page lacks without an error.
    QStringEncoder encoder(page.codec);
    QStringDecoder decoder(page.codec);
    const QByteArray bytes = encoder.encode(text);
    return encoder.isValid() && decoder.isValid() && !encoder.hasError() && QString(decoder.decode(bytes)) == text;
}

// The first code page that has every character of the names (ANSI_1252 for ASCII ones), or
// ANSI_1252 when none has.
const CodePage &codePageFor(const std::vector<QString> &names)
{
    for (const CodePage &page : codePages)
        if (std::all_of(names.begin(), names.end(), [&](const QString &name) { return encodes(name, page); }))
            return page;
    return codePages.front();
}

// A character in a code page, or empty when the page has none for it.
QByteArray encoded(QChar c, const CodePage &page)
{
    if (c.unicode() < 0x80)
        return QByteArray(1, static_cast<char>(c.unicode()));
    if (!encodes(QString(c), page))
        return {};
    QStringEncoder encoder(page.codec);
    return encoder.encode(QStringView(&c, 1));
}

// Text as an AC1015 file holds it: in its code page, a character the page lacks as AutoCAD's escape
// \U+XXXX.
QByteArray dxfText(const QString &text, const CodePage &page)
{
    if (isAscii(text))
        return text.toLatin1();
    if (encodes(text, page)) {
        QStringEncoder encoder(page.codec);
        return encoder.encode(text);
    }
    QByteArray out;
    for (const QChar c : text) {
        const QByteArray bytes = encoded(c, page);
        out += bytes.isEmpty() ? "\\U+" + QByteArray::number(c.unicode(), 16).toUpper().rightJustified(4, '0') : bytes;
    }
    return out;
}

struct Layer
{
    QString name;
    int aci = 7;
    QByteArray written; // the name in the file's code page
};

// One layer per distinct name the curves leave (AutoCAD's names are the same regardless of case), so
// that curves read from one layer of a DXF are written on that one layer again; never "0" or
// "Defpoints" (not plotted: such a name gets " (2)"). The layer's colour is its first curve's. The
// index of each curve's layer, -1 for the layer "0".
std::vector<int> layersOf(std::span<const DxfCurve> curves, std::vector<Layer> &layers)
{
    QHash<QString, int> byName;
    std::vector<int> index;
    for (const DxfCurve &c : curves) {
        QString name = layerNameOf(c.name);
        if (name.isEmpty()) {
            index.push_back(-1);
            continue;
        }
        if (name.toCaseFolded() == QLatin1String("0") || name.toCaseFolded() == QLatin1String("defpoints"))
            name = name.left(251) + QStringLiteral(" (2)");
        const QString key = name.toCaseFolded();
        if (const auto found = byName.constFind(key); found != byName.constEnd()) {
            index.push_back(*found);
            continue;
        }
        const int rgb = rgbOf(c.color);
        layers.push_back({name, rgb >= 0 ? nearestAci(rgb) : 7, {}});
        byName.insert(key, static_cast<int>(layers.size()) - 1);
        index.push_back(static_cast<int>(layers.size()) - 1);
    }
    return index;
}

// A block of the drawing besides model and paper space: its record's, BLOCK's and ENDBLK's handles.
struct BlockHandles
{
    QByteArray name;
    unsigned record = 0, begin = 0, end = 0;
};

void writeTables(Writer &w, const std::vector<Layer> &layers, const geo::Box &extents, unsigned firstLayer,
                 const std::vector<BlockHandles> &blocks = {})
{
    w.pair(0, "SECTION");
    w.pair(2, "TABLES");

    // The active viewport shows the whole drawing: its extents' middle, their height or more.
    w.table("VPORT", VportTable, 1);
    w.record("VPORT", ActiveVport, VportTable, "AcDbViewportTableRecord", "*Active");
    const double aspect = 1.5; // of the view, width to height
    const geo::Point middle = extents.isEmpty() ? geo::Point(0, 0) : geo::Point(extents.center());
    const double height = extents.isEmpty() ? 1.0 : 1.05 * std::max(extents.sizes().y(), extents.sizes().x() / aspect);
    w.number(10, 0.0); // lower left and upper right corners, in the screen's fractions
    w.number(20, 0.0);
    w.number(11, 1.0);
    w.number(21, 1.0);
    w.number(12, middle.x()); // the view's middle
    w.number(22, middle.y());
    w.number(13, 0.0); // snap base and spacing, grid spacing
    w.number(23, 0.0);
    w.number(14, 1.0);
    w.number(24, 1.0);
    w.number(15, 10.0);
    w.number(25, 10.0);
    w.point3(16, 0.0, 0.0, 1.0); // seen from above
    w.point3(17, 0.0, 0.0, 0.0); // target point
    w.number(40, height > 0 ? height : 1.0);
    w.number(41, aspect);
    w.number(42, 50.0); // lens length, front and back clipping, snap rotation, view twist
    w.number(43, 0.0);
    w.number(44, 0.0);
    w.number(50, 0.0);
    w.number(51, 0.0);
    w.integer(71, 0);    // view mode
    w.integer(72, 1000); // circle zoom percent
    w.integer(73, 1);    // fast zoom
    w.integer(74, 3);    // UCS icon on, at the origin
    w.integer(75, 0);    // snap, grid, snap style, isometric plane: off
    w.integer(76, 0);
    w.integer(77, 0);
    w.integer(78, 0);
    w.pair(0, "ENDTAB");

    w.table("LTYPE", LtypeTable, 3);
    for (const auto &[h, name, description] : {std::tuple{ByBlockLtype, "ByBlock", ""},
                                               {ByLayerLtype, "ByLayer", ""},
                                               {ContinuousLtype, "Continuous", "Solid line"}}) {
        w.record("LTYPE", h, LtypeTable, "AcDbLinetypeTableRecord", name);
        w.pair(3, description);
        w.integer(72, 65); // alignment code, always "A"
        w.integer(73, 0);  // no dashes
        w.number(40, 0.0); // pattern length
    }
    w.pair(0, "ENDTAB");

    w.table("LAYER", LayerTable, static_cast<int>(layers.size()) + 1);
    const auto layer = [&](unsigned h, QByteArrayView name, int aci) {
        w.record("LAYER", h, LayerTable, "AcDbLayerTableRecord", name);
        w.integer(62, aci);
        w.pair(6, "Continuous");
        w.integer(370, -3); // line weight: the default
    };
    layer(Layer0, "0", 7);
    for (std::size_t i = 0; i < layers.size(); ++i)
        layer(firstLayer + static_cast<unsigned>(i), layers[i].written, layers[i].aci);
    w.pair(0, "ENDTAB");

    w.table("STYLE", StyleTable, 1);
    w.record("STYLE", StandardStyle, StyleTable, "AcDbTextStyleTableRecord", "Standard");
    w.number(40, 0.0); // fixed height: none
    w.number(41, 1.0); // width factor
    w.number(50, 0.0); // oblique angle
    w.integer(71, 0);  // generation flags
    w.number(42, 2.5); // last height used
    w.pair(3, "txt");  // font file
    w.pair(4, "");     // big font file
    w.pair(0, "ENDTAB");

    w.table("VIEW", ViewTable, 0);
    w.pair(0, "ENDTAB");
    w.table("UCS", UcsTable, 0);
    w.pair(0, "ENDTAB");

    w.table("APPID", AppidTable, 1);
    w.record("APPID", AcadAppid, AppidTable, "AcDbRegAppTableRecord", "ACAD");
    w.pair(0, "ENDTAB");

    w.table("DIMSTYLE", DimstyleTable, 1);
    w.pair(100, "AcDbDimStyleTable");
    w.record("DIMSTYLE", StandardDimstyle, DimstyleTable, "AcDbDimStyleTableRecord", "Standard", 105);
    w.pair(0, "ENDTAB");

    w.table("BLOCK_RECORD", BlockRecordTable, 2 + static_cast<int>(blocks.size()));
    for (const auto &[handle, name, layout] : {std::tuple{ModelSpaceRecord, "*Model_Space", ModelLayout},
                                               std::tuple{PaperSpaceRecord, "*Paper_Space", PaperLayout}}) {
        w.pair(0, "BLOCK_RECORD");
        w.hex(5, handle);
        w.hex(330, BlockRecordTable);
        w.pair(100, "AcDbSymbolTableRecord");
        w.pair(100, "AcDbBlockTableRecord");
        w.pair(2, name);
        w.hex(340, layout);
    }
    for (const BlockHandles &b : blocks) {
        w.pair(0, "BLOCK_RECORD");
        w.hex(5, b.record);
        w.hex(330, BlockRecordTable);
        w.pair(100, "AcDbSymbolTableRecord");
        w.pair(100, "AcDbBlockTableRecord");
        w.pair(2, b.name);
        w.pair(340, "0"); // no layout: not a space
    }
    w.pair(0, "ENDTAB");

    w.pair(0, "ENDSEC");
}

// The two blocks every drawing has, model space and paper space, empty here (the entities of model
// space are in the ENTITIES section).
void writeBlocks(Writer &w, const QByteArray &more = {})
{
    w.pair(0, "SECTION");
    w.pair(2, "BLOCKS");
    for (const auto &[record, begin, end, name, paper] :
         {std::tuple{ModelSpaceRecord, ModelSpaceBlock, ModelSpaceEnd, "*Model_Space", false},
          {PaperSpaceRecord, PaperSpaceBlock, PaperSpaceEnd, "*Paper_Space", true}}) {
        w.pair(0, "BLOCK");
        w.hex(5, begin);
        w.hex(330, record);
        w.pair(100, "AcDbEntity");
        if (paper)
            w.integer(67, 1);
        w.pair(8, "0");
        w.pair(100, "AcDbBlockBegin");
        w.pair(2, name);
        w.integer(70, 0);
        w.point3(10, 0.0, 0.0, 0.0);
        w.pair(3, name);
        w.pair(1, "");
        w.pair(0, "ENDBLK");
        w.hex(5, end);
        w.hex(330, record);
        w.pair(100, "AcDbEntity");
        if (paper)
            w.integer(67, 1);
        w.pair(8, "0");
        w.pair(100, "AcDbBlockEnd");
    }
    w.out += more;
    w.pair(0, "ENDSEC");
}

// The root dictionary with ACAD_GROUP (no groups) and ACAD_LAYOUT (the layouts Model and Layout1,
// whose plot settings plot at 1:1 on no device).
void writeObjects(Writer &w, const geo::Box &extents, bool millimetres)
{
    w.pair(0, "SECTION");
    w.pair(2, "OBJECTS");
    w.pair(0, "DICTIONARY");
    w.hex(5, RootDictionary);
    w.pair(330, "0");
    w.pair(100, "AcDbDictionary");
    w.integer(281, 1); // records are kept when the dictionary is copied
    w.pair(3, "ACAD_GROUP");
    w.hex(350, GroupDictionary);
    w.pair(3, "ACAD_LAYOUT");
    w.hex(350, LayoutDictionary);

    w.ownedObject("DICTIONARY", GroupDictionary, RootDictionary);
    w.pair(100, "AcDbDictionary");
    w.integer(281, 1);

    w.ownedObject("DICTIONARY", LayoutDictionary, RootDictionary);
    w.pair(100, "AcDbDictionary");
    w.integer(281, 1);
    w.pair(3, "Layout1");
    w.hex(350, PaperLayout);
    w.pair(3, "Model");
    w.hex(350, ModelLayout);

    const bool empty = extents.isEmpty();
    for (const auto &[h, name, record, model] : {std::tuple{ModelLayout, "Model", ModelSpaceRecord, true},
                                                 {PaperLayout, "Layout1", PaperSpaceRecord, false}}) {
        w.ownedObject("LAYOUT", h, LayoutDictionary);
        w.pair(100, "AcDbPlotSettings");
        w.pair(1, "");            // page setup name
        w.pair(2, "none_device"); // plot configuration, paper size, view name
        w.pair(4, "");
        w.pair(6, "");
        for (int code = 40; code <= 49; ++code) // margins, paper size, plot origin, window
            w.number(code, 0.0);
        w.number(140, 0.0);
        w.number(141, 0.0);
        w.number(142, 1.0); // scale 1:1
        w.number(143, 1.0);
        w.integer(70, model ? 1024 : 0); // the model layout's plot settings
        w.integer(72, millimetres ? 1 : 0);
        w.integer(73, 0);  // no rotation
        w.integer(74, 5);  // plot the layout
        w.pair(7, "");     // plot style table
        w.integer(75, 16); // standard scale 1:1
        w.number(147, 1.0);
        w.number(148, 0.0);
        w.number(149, 0.0);
        w.pair(100, "AcDbLayout");
        w.pair(1, name);
        w.integer(70, 1);                              // line type scale by viewport
        w.integer(71, model ? 0 : 1);                  // tab order
        w.number(10, empty ? 0.0 : extents.min().x()); // limits
        w.number(20, empty ? 0.0 : extents.min().y());
        w.number(11, empty ? 1.0 : extents.max().x());
        w.number(21, empty ? 1.0 : extents.max().y());
        w.point3(12, 0.0, 0.0, 0.0); // insertion base
        w.point3(14, empty ? 1e20 : extents.min().x(), empty ? 1e20 : extents.min().y(), empty ? 1e20 : 0.0);
        w.point3(15, empty ? -1e20 : extents.max().x(), empty ? -1e20 : extents.max().y(), empty ? -1e20 : 0.0);
        w.number(146, 0.0);          // elevation
        w.point3(13, 0.0, 0.0, 0.0); // the UCS: origin, x and y axes
        w.point3(16, 1.0, 0.0, 0.0);
        w.point3(17, 0.0, 1.0, 0.0);
        w.integer(76, 0); // orthographic type: none
        w.hex(330, record);
    }
    w.pair(0, "ENDSEC");
}

// HEADER and CLASSES: the version, the code page, the next handle, the units and the extents.
void writeHeader(Writer &w, const CodePage &page, unsigned handseed, int insunits, const geo::Box &extents)
{
    w.pair(0, "SECTION");
    w.pair(2, "HEADER");
    w.pair(9, "$ACADVER");
    w.pair(1, "AC1015");
    w.pair(9, "$DWGCODEPAGE");
    w.pair(3, page.dxf);
    w.pair(9, "$HANDSEED");
    w.hex(5, handseed);
    w.pair(9, "$INSUNITS");
    w.integer(70, insunits);
    w.pair(9, "$MEASUREMENT");
    w.integer(70, insunits == 1 ? 0 : 1);
    // An empty drawing's extents are AutoCAD's: from 1e20 to -1e20.
    w.pair(9, "$EXTMIN");
    if (extents.isEmpty())
        w.point3(10, 1e20, 1e20, 1e20);
    else
        w.point(10, extents.min());
    w.pair(9, "$EXTMAX");
    if (extents.isEmpty())
        w.point3(10, -1e20, -1e20, -1e20);
    else
        w.point(10, extents.max());
    w.pair(0, "ENDSEC");
    w.pair(0, "SECTION");
    w.pair(2, "CLASSES");
    w.pair(0, "ENDSEC");
}

// A TEXT entity (AcDbText) at p, `height` high, on the writer's layer.
void writeText(Writer &w, const geo::Point &p, double height, const QByteArray &text)
{
    w.entity("TEXT", "AcDbText");
    w.point(10, p);
    w.number(40, height);
    w.pair(1, text);
    w.pair(100, "AcDbText");
}

// A POINT entity at p on the writer's layer; `angle` (degrees) when it is not 0.
void writePoint(Writer &w, const geo::Point &p, double angle = 0.0)
{
    w.entity("POINT", "AcDbPoint");
    ++w.entities;
    ++w.points;
    w.point(10, p);
    if (angle != 0.0)
        w.number(50, angle);
}

// The degrees counter-clockwise from the x axis of a direction, in [0, 360).
double degreesOf(const geo::Point &d)
{
    double a = std::atan2(d.y(), d.x()) * 180.0 / std::numbers::pi;
    if (a < 0)
        a += 360.0;
    return a >= 360.0 ? 0.0 : a;
}

// A piece's marks on the standard's layers (the block's entities; see AamaPiece).
void writeMarks(Writer &e, const AamaPiece &piece, double scale)
{
    const PieceMarks &m = *piece.marks;
    const geo::PiecewiseBezier &own = piece.sew.isEmpty() ? piece.cut : piece.sew;
    // Layer 4: each notch where it meets the cut line (carried square across from the seam), its direction
    // as the point's angle; its kind on D6673's layer (80 T, 81 castle, 82 check, 83 U, 84 V; slit: none).
    for (const Notch &n : m.notches) {
        const CurvePlace place = placeAtLength(own, n.position);
        const geo::Point direction = notchDirection(own, place, n.angle);
        geo::Point at = place.point;
        if (!piece.sew.isEmpty())
            at = piece.cut.nearest(place.point).point;
        const double angle = degreesOf(direction);
        e.layer = "4";
        writePoint(e, at * scale, angle);
        if (n.kind != NotchKind::Slit) {
            e.layer = n.kind == NotchKind::Castle ? "81" : "84";
            writePoint(e, at * scale, angle);
        }
    }
    if (m.fold) {
        e.layer = "6";
        writeLines(e, {m.fold->a * scale, m.fold->b * scale}, false);
    }
    if (m.grainline) {
        e.layer = "7";
        writeLines(e, {m.grainline->a * scale, m.grainline->b * scale}, false);
    }
    e.layer = "13";
    for (const geo::Point &p : m.drillHoles)
        writePoint(e, p * scale);
}

// ASTM D6673 (AAMA DXF): each piece a block on the standard's numbered layers, inserted once at the
// origin (its block's base point), so the pieces lie where they were drawn.
QByteArray buildAama(std::span<const AamaPiece> pieces, const DxfExportOptions &options, qint64 &entities,
                     qint64 &points)
{
    const auto [insunits, scale] = fileUnits(options.units);
    const double tolerance = (options.tolerance > 0 ? options.tolerance : defaultDxfTolerance(options.units)) * scale;
    geo::Box extents; // in the file's units
    for (const AamaPiece &piece : pieces)
        if (!piece.cut.isEmpty()) {
            const geo::Box b = piece.cut.boundingBox();
            extents.extend(b.min() * scale);
            extents.extend(b.max() * scale);
        }
    // The layers of the standard that Kontur writes, with the colours garment CAD shows them in.
    std::vector<Layer> layers{{QStringLiteral("1"), 7, "1"},   {QStringLiteral("4"), 1, "4"},
                              {QStringLiteral("6"), 6, "6"},   {QStringLiteral("7"), 5, "7"},
                              {QStringLiteral("8"), 4, "8"},   {QStringLiteral("13"), 2, "13"},
                              {QStringLiteral("14"), 3, "14"}, {QStringLiteral("81"), 1, "81"},
                              {QStringLiteral("84"), 1, "84"}};
    std::vector<QString> names;
    for (const AamaPiece &piece : pieces) {
        names.push_back(piece.name);
        if (piece.marks) {
            names.push_back(piece.marks->size);
            names.push_back(piece.marks->material);
        }
    }
    const CodePage &page = codePageFor(names);
    // Block names: the piece's name as a layer name is made (AutoCAD's refused characters as "_"),
    // unique regardless of case; "Piece N" for a piece without one.
    std::vector<BlockHandles> blocks;
    QSet<QString> taken;
    unsigned next = FirstFree + static_cast<unsigned>(layers.size());
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        QString base = layerNameOf(pieces[i].name);
        if (base.isEmpty() || base.startsWith(QLatin1Char('*')))
            base = QStringLiteral("Piece %1").arg(i + 1);
        QString name = base;
        for (int n = 2; taken.contains(name.toCaseFolded()); ++n)
            name = base.left(240) + QStringLiteral(" (%1)").arg(n);
        taken.insert(name.toCaseFolded());
        blocks.push_back({dxfText(name, page), next, next + 1, next + 2});
        next += 3;
    }
    Writer e;
    e.handle = next;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const AamaPiece &piece = pieces[i];
        const BlockHandles &b = blocks[i];
        e.pair(0, "BLOCK");
        e.hex(5, b.begin);
        e.hex(330, b.record);
        e.pair(100, "AcDbEntity");
        e.pair(8, "1");
        e.pair(100, "AcDbBlockBegin");
        e.pair(2, b.name);
        e.integer(70, 0);
        e.point3(10, 0.0, 0.0, 0.0);
        e.pair(3, b.name);
        e.pair(1, "");
        e.owner = b.record;
        e.rgb = -1;
        // Layer 1: the cut line (the allowance's outline, else the piece's own curve).
        e.layer = "1";
        for (const auto &run : runsOf(piece.cut, scale))
            writeRun(e, run, piece.cut.isClosed(), options, tolerance);
        // Layer 14: the sew line, where an allowance lies around it.
        if (!piece.sew.isEmpty()) {
            e.layer = "14";
            for (const auto &run : runsOf(piece.sew, scale))
                writeRun(e, run, piece.sew.isClosed(), options, tolerance);
        }
        // Layer 8: the internal lines.
        e.layer = "8";
        for (const geo::PiecewiseBezier &line : piece.internal)
            for (const auto &run : runsOf(line, scale))
                writeRun(e, run, line.isClosed(), options, tolerance);
        // Layers 4, 6, 7 and 13: the piece's own marks; no grain line where the piece has none.
        if (piece.marks)
            writeMarks(e, piece, scale);
        // Layer 1: the annotations the standard names, in the middle of the piece.
        e.layer = "1";
        const geo::Box box = piece.cut.boundingBox();
        const double height = std::max(box.sizes().y() * scale / 40, 1e-6);
        geo::Point at = box.center() * scale - geo::Point(box.sizes().x() * scale / 4, 0);
        const auto text = [&](const QByteArray &line) {
            writeText(e, at, height, line);
            at.y() -= 1.5 * height;
        };
        text("Piece Name: " + dxfText(piece.name.isEmpty() ? QString::fromUtf8(b.name) : piece.name, page));
        if (piece.marks && !piece.marks->size.isEmpty())
            text("Size: " + dxfText(piece.marks->size, page));
        text("Quantity: " + QByteArray::number(piece.marks ? piece.marks->quantity : 1));
        if (piece.marks && !piece.marks->material.isEmpty())
            text("Material: " + dxfText(piece.marks->material, page));
        if (piece.marks && piece.marks->fold)
            text("Annotation: On fold");
        e.pair(0, "ENDBLK");
        e.hex(5, b.end);
        e.hex(330, b.record);
        e.pair(100, "AcDbEntity");
        e.pair(8, "1");
        e.pair(100, "AcDbBlockEnd");
    }
    QByteArray blockText = std::move(e.out);
    e.out.clear();
    e.owner = ModelSpaceRecord;
    e.pair(0, "SECTION");
    e.pair(2, "ENTITIES");
    e.layer = "1";
    for (const BlockHandles &b : blocks) {
        e.entity("INSERT", "AcDbBlockReference");
        e.pair(2, b.name);
        e.point(10, geo::Point(0, 0));
    }
    e.pair(0, "ENDSEC");

    Writer w;
    w.pair(999, "Written by Kontur: ASTM D6673 (AAMA) pieces, one block each");
    writeHeader(w, page, e.handle, insunits, extents);
    writeTables(w, layers, extents, FirstFree, blocks);
    writeBlocks(w, blockText);
    w.out += e.out;
    writeObjects(w, extents, insunits != 1 && insunits != 0);
    w.pair(0, "EOF");
    entities = e.entities;
    points = e.points;
    return std::move(w.out);
}

QByteArray build(std::span<const DxfCurve> curves, const DxfExportOptions &options, qint64 &entities, qint64 &points)
{
    const auto [insunits, scale] = fileUnits(options.units);
    const double tolerance = (options.tolerance > 0 ? options.tolerance : defaultDxfTolerance(options.units)) * scale;
    geo::Box box;
    for (const DxfCurve &c : curves)
        if (!c.curve.isEmpty())
            box.extend(c.curve.boundingBox());
    geo::Box extents; // in the file's units
    if (!box.isEmpty()) {
        extents.extend(box.min() * scale);
        extents.extend(box.max() * scale);
    }
    std::vector<Layer> layers;
    const std::vector<int> layerOf = layersOf(curves, layers);
    std::vector<QString> names;
    for (const Layer &l : layers)
        names.push_back(l.name);
    const CodePage &page = codePageFor(names);
    for (Layer &l : layers)
        l.written = dxfText(l.name, page);

    // The entities first: $HANDSEED, in the header, must exceed their handles.
    Writer e;
    e.handle = FirstFree + static_cast<unsigned>(layers.size());
    e.pair(0, "SECTION");
    e.pair(2, "ENTITIES");
    for (std::size_t i = 0; i < curves.size(); ++i) {
        const DxfCurve &c = curves[i];
        e.layer = layerOf[i] < 0 ? QByteArray("0") : layers[static_cast<std::size_t>(layerOf[i])].written;
        e.rgb = rgbOf(c.color);
        const auto runs = runsOf(c.curve, scale);
        for (const auto &run : runs)
            writeRun(e, run, c.curve.isClosed() && runs.size() == 1, options, tolerance);
    }
    e.pair(0, "ENDSEC");

    Writer w;
    w.pair(999, "Written by Kontur: exact Bezier control points (SPLINE) or a flattened polyline (LWPOLYLINE)");
    writeHeader(w, page, e.handle, insunits, extents);
    writeTables(w, layers, extents, FirstFree);
    writeBlocks(w);
    w.out += e.out;
    writeObjects(w, extents, insunits != 1 && insunits != 0);
    w.pair(0, "EOF");
    entities = e.entities;
    points = e.points;
    return std::move(w.out);
}

} // namespace

QByteArray exportDxf(std::span<const DxfCurve> curves, const DxfExportOptions &options)
{
    qint64 entities = 0, points = 0;
    return build(curves, options, entities, points);
}

Result<std::vector<AamaPiece>> aamaPieces(const std::vector<CurveRecord> &records)
{
    const int n = static_cast<int>(records.size());
    std::vector<std::optional<geo::PiecewiseBezier>> shapes(records.size());
    std::vector<int> sourceOf(records.size(), -1);
    for (int i = 0; i < n; ++i) {
        const CurveRecord &r = records[static_cast<std::size_t>(i)];
        if (!r.visible)
            continue;
        auto shape = curveShape(r);
        if (!shape) {
            Error e = shape.error();
            e.path = QStringLiteral("curves[%1]").arg(i);
            return e;
        }
        shapes[static_cast<std::size_t>(i)] = std::move(shape).value();
        if (const auto seam = seamFromSettings(r.settings, n))
            sourceOf[static_cast<std::size_t>(i)] = seam->source;
    }
    std::vector<AamaPiece> pieces;
    std::vector<int> pieceOf(records.size(), -1);
    for (int i = 0; i < n; ++i) {
        const auto &shape = shapes[static_cast<std::size_t>(i)];
        if (!shape || sourceOf[static_cast<std::size_t>(i)] >= 0 || !shape->isClosed() || shape->isEmpty())
            continue;
        AamaPiece piece;
        piece.name = records[static_cast<std::size_t>(i)].name;
        piece.cut = *shape;
        piece.marks = pieceFromSettings(records[static_cast<std::size_t>(i)].settings);
        for (int k = 0; k < n; ++k)
            if (sourceOf[static_cast<std::size_t>(k)] == i && shapes[static_cast<std::size_t>(k)] &&
                !shapes[static_cast<std::size_t>(k)]->isEmpty()) {
                piece.sew = *shape;
                piece.cut = *shapes[static_cast<std::size_t>(k)];
                break;
            }
        pieceOf[static_cast<std::size_t>(i)] = static_cast<int>(pieces.size());
        pieces.push_back(std::move(piece));
    }
    for (int i = 0; i < n; ++i) {
        const auto &shape = shapes[static_cast<std::size_t>(i)];
        if (!shape || shape->isClosed() || shape->isEmpty() || sourceOf[static_cast<std::size_t>(i)] >= 0)
            continue;
        const geo::Box box = shape->boundingBox();
        for (AamaPiece &piece : pieces)
            if (piece.cut.boundingBox().contains(box)) {
                piece.internal.push_back(*shape);
                break;
            }
    }
    return pieces;
}

std::vector<QString> piecesWithoutGrainline(std::span<const AamaPiece> pieces)
{
    std::vector<QString> names;
    for (const AamaPiece &piece : pieces)
        if (!piece.marks || !piece.marks->grainline)
            names.push_back(piece.name);
    return names;
}

QByteArray exportAamaDxf(std::span<const AamaPiece> pieces, const DxfExportOptions &options)
{
    qint64 entities = 0, points = 0;
    return buildAama(pieces, options, entities, points);
}

namespace {

// Refuses what the reader would refuse (`limits`) or a drawing with numbers that are not finite;
// else replaces the file atomically.
Result<Ok> writeChecked(const QString &path, const QByteArray &bytes, bool nonFinite, qint64 entities, qint64 points,
                        const Limits &limits)
{
    Error e;
    e.file = path;
    if (nonFinite)
        return NonFiniteWatch::error(path, QStringLiteral("the drawing"));
    if (entities > limits.maxCurves) {
        e.code = ErrorCode::TooManyCurves;
        e.message = QStringLiteral("the drawing cannot be written: %1 entities; a file holds at most %2")
                        .arg(entities)
                        .arg(limits.maxCurves);
        return e;
    }
    if (points > limits.maxPoints || bytes.size() > limits.maxFileBytes) {
        e.code = points > limits.maxPoints ? ErrorCode::TooManyPoints : ErrorCode::FileTooLarge;
        e.message = QStringLiteral("the drawing cannot be written: %1 points in %2 bytes; a file holds at most %3 "
                                   "points in %4 bytes")
                        .arg(points)
                        .arg(bytes.size())
                        .arg(limits.maxPoints)
                        .arg(limits.maxFileBytes);
        return e;
    }
    return writeFileAtomically(path, bytes);
}

} // namespace

Result<Ok> writeAamaDxf(const QString &path, std::span<const AamaPiece> pieces, const DxfExportOptions &options,
                        const Limits &limits)
{
    for (const AamaPiece &piece : pieces)
        for (const geo::PiecewiseBezier *c : {&piece.cut, &piece.sew})
            for (const geo::Bezier &b : c->segments())
                for (const geo::Point &p : b.controlPoints())
                    if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
                        return NonFiniteWatch::error(path, QStringLiteral("the drawing"));
    qint64 entities = 0, points = 0;
    const NonFiniteWatch watch;
    const QByteArray bytes = buildAama(pieces, options, entities, points);
    return writeChecked(path, bytes, watch.seen(), entities, points, limits);
}

Result<Ok> writeDxf(const QString &path, std::span<const DxfCurve> curves, const DxfExportOptions &options,
                    const Limits &limits)
{
    Error e;
    e.file = path;
    for (const DxfCurve &c : curves)
        for (const geo::Bezier &b : c.curve.segments())
            for (const geo::Point &p : b.controlPoints())
                if (!std::isfinite(p.x()) || !std::isfinite(p.y())) {
                    e.code = ErrorCode::NumberOutOfRange;
                    e.message =
                        QStringLiteral("the drawing cannot be written: a coordinate of \"%1\" is not a finite number")
                            .arg(c.name);
                    return e;
                }
    qint64 entities = 0, points = 0;
    const NonFiniteWatch watch;
    const QByteArray bytes = build(curves, options, entities, points);
    return writeChecked(path, bytes, watch.seen(), entities, points, limits);
}

QString aciColorName(int aci)
{
    if (aci < 1 || aci > 255 || aci == 7)
        return QStringLiteral("#000000"); // 7 is black on paper (and what the writer makes of black)
    const std::array<int, 3> c = aciColour(aci);
    return QStringLiteral("#%1").arg((c[0] << 16) | (c[1] << 8) | c[2], 6, 16, QLatin1Char('0'));
}

} // namespace kontur::io
