// DXF export (see dxf.h): the layers. A curve's name as a layer name, the code page its text is
// written in ($DWGCODEPAGE, with AutoCAD's \U+XXXX escape for what the page lacks), and the AutoCAD
// Color Index (ACI) of a colour and back. The writer's insides: dxfwrite_p.h.
#include "io/dxf.h"

#include "io/dxfwrite_p.h"

#include <QHash>
#include <QStringDecoder>
#include <QStringEncoder>

#include <algorithm>
#include <array>
#include <cmath>

namespace kontur::io::dxfwrite {

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

// The pages Kontur writes, in the order they are tried (see CodePage).
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

} // namespace

int rgbOf(const QString &color)
{
    if (!isColorName(color))
        return -1;
    return static_cast<int>(QStringView(color).mid(1).toUInt(nullptr, 16));
}

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

const CodePage &codePageFor(const std::vector<QString> &names)
{
    for (const CodePage &page : codePages)
        if (std::all_of(names.begin(), names.end(), [&](const QString &name) { return encodes(name, page); }))
            return page;
    return codePages.front();
}

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

} // namespace kontur::io::dxfwrite

namespace kontur::io {

QString aciColorName(int aci)
{
    if (aci < 1 || aci > 255 || aci == 7)
        return QStringLiteral("#000000"); // 7 is black on paper (and what the writer makes of black)
    const std::array<int, 3> c = dxfwrite::aciColour(aci);
    return QStringLiteral("#%1").arg((c[0] << 16) | (c[1] << 8) | c[2], 6, 16, QLatin1Char('0'));
}

} // namespace kontur::io
