// DXF export (see dxf.h): the drawing's fixed structure as AutoCAD writes a new one and the "DXF
// Reference" (AutoCAD 2000) lists its groups: HEADER and CLASSES, the nine symbol tables (VPORT
// *Active, the line types ByBlock/ByLayer/Continuous, the layers, STYLE and DIMSTYLE Standard, empty
// VIEW and UCS, APPID ACAD, BLOCK_RECORD *Model_Space and *Paper_Space), BLOCKS (their BLOCK/ENDBLK
// pairs) and OBJECTS (the root dictionary, ACAD_GROUP and ACAD_LAYOUT with the layouts Model and
// Layout1 and their plot settings), written group by group; and the whole drawing around the
// entities (writeDrawing). The writer's insides: dxfwrite_p.h.
#include "io/dxf.h"

#include "io/dxfwrite_p.h"

#include <algorithm>
#include <tuple>

namespace kontur::io::dxfwrite {

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

void writeTables(Writer &w, const std::vector<Layer> &layers, const geo::Box &extents, unsigned firstLayer,
                 const std::vector<BlockHandles> &blocks)
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

void writeBlocks(Writer &w, const QByteArray &more)
{
    w.pair(0, "SECTION");
    w.pair(2, "BLOCKS");
    for (const auto &[record, begin, end, name, paper] :
         {std::tuple{ModelSpaceRecord, ModelSpaceBlock, ModelSpaceEnd, "*Model_Space", false},
          {PaperSpaceRecord, PaperSpaceBlock, PaperSpaceEnd, "*Paper_Space", true}}) {
        w.blockBegin(name, begin, record, "0", paper);
        w.blockEnd(end, record, "0", paper);
    }
    w.out += more;
    w.pair(0, "ENDSEC");
}

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

QByteArray writeDrawing(const char *comment, const Writer &e, const CodePage &page, int insunits,
                        const geo::Box &extents, const std::vector<Layer> &layers,
                        const std::vector<BlockHandles> &blocks, const QByteArray &blockText, qint64 &entities,
                        qint64 &points)
{
    Writer w;
    w.pair(999, comment);
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

} // namespace kontur::io::dxfwrite
