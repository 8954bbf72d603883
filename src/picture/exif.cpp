// The focal length from EXIF; see exif.h.
#include "picture/exif.h"

#include <QtEndian>

#include <cstdint>
#include <optional>

namespace kontur {

namespace {

// Bounds-checked reads of a TIFF block's integers in its byte order.
class TiffReader
{
public:
    explicit TiffReader(const QByteArray &data)
        : m_data(data)
    {
    }
    bool byteOrder()
    {
        if (m_data.startsWith(QByteArray("II*\0", 4)))
            m_little = true;
        else if (m_data.startsWith(QByteArray("MM\0*", 4)))
            m_little = false;
        else
            return false;
        return true;
    }
    [[nodiscard]] std::optional<std::uint32_t> u16(qsizetype at) const { return read(at, 2); }
    [[nodiscard]] std::optional<std::uint32_t> u32(qsizetype at) const { return read(at, 4); }

private:
    [[nodiscard]] std::optional<std::uint32_t> read(qsizetype at, int bytes) const
    {
        if (at < 0 || at + bytes > m_data.size())
            return std::nullopt;
        const char *p = m_data.constData() + at;
        if (bytes == 2)
            return m_little ? qFromLittleEndian<quint16>(p) : qFromBigEndian<quint16>(p);
        return m_little ? qFromLittleEndian<quint32>(p) : qFromBigEndian<quint32>(p);
    }
    const QByteArray &m_data;
    bool m_little = true;
};

// The value of a SHORT or LONG tag (count 1) in the IFD at `ifd`, or of a LONG offset tag.
std::optional<std::uint32_t> tagValue(const TiffReader &r, std::uint32_t ifd, std::uint32_t wanted)
{
    const auto count = r.u16(ifd);
    if (!count || *count > 1000)
        return std::nullopt;
    for (std::uint32_t i = 0; i < *count; ++i) {
        const qsizetype entry = static_cast<qsizetype>(ifd) + 2 + 12 * static_cast<qsizetype>(i);
        const auto tag = r.u16(entry), type = r.u16(entry + 2);
        if (!tag || !type)
            return std::nullopt;
        if (*tag != wanted)
            continue;
        if (*type == 3) // SHORT: left-justified in the 4-byte value field
            return r.u16(entry + 8);
        if (*type == 4) // LONG
            return r.u32(entry + 8);
        return std::nullopt;
    }
    return std::nullopt;
}

} // namespace

double exifFocal35mm(const QByteArray &tiff)
{
    TiffReader r(tiff);
    if (!r.byteOrder())
        return 0.0;
    const auto ifd0 = r.u32(4);
    if (!ifd0)
        return 0.0;
    const auto exifIfd = tagValue(r, *ifd0, 0x8769); // ExifIFDPointer
    if (!exifIfd)
        return 0.0;
    const auto focal = tagValue(r, *exifIfd, 0xA405); // FocalLengthIn35mmFilm, mm
    return focal ? static_cast<double>(*focal) : 0.0;
}

QByteArray jpegExifBlock(const QByteArray &jpeg)
{
    if (jpeg.size() < 4 || static_cast<std::uint8_t>(jpeg[0]) != 0xFF || static_cast<std::uint8_t>(jpeg[1]) != 0xD8)
        return {};
    qsizetype at = 2;
    // Marker segments up to the start of scan: FF xx, then a big-endian length that counts itself.
    while (at + 4 <= jpeg.size() && static_cast<std::uint8_t>(jpeg[at]) == 0xFF) {
        const auto marker = static_cast<std::uint8_t>(jpeg[at + 1]);
        if (marker == 0xDA || marker == 0xD9) // start of scan, end of image
            break;
        const qsizetype length = qFromBigEndian<quint16>(jpeg.constData() + at + 2);
        if (length < 2)
            break;
        const QByteArray exif("Exif\0\0", 6);
        if (marker == 0xE1 && length >= 8 && jpeg.mid(at + 4, 6) == exif)
            return jpeg.mid(at + 10, length - 8);
        at += 2 + length;
    }
    return {};
}

} // namespace kontur
