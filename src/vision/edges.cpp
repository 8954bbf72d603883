// Segmentation and sub-pixel edge points for the outline tracer (docs/vision.md, "Outlines").
#include "vision/edges.h"

#include "vision/lineband.h"
#include "vision/pixels.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace kontur::vision::detail {

namespace {

double signedArea(const std::vector<cv::Point> &c)
{
    double a = 0.0;
    for (std::size_t i = 0, j = c.size() - 1; i < c.size(); j = i++)
        a += static_cast<double>(c[j].x) * c[i].y - static_cast<double>(c[i].x) * c[j].y;
    return 0.5 * a;
}

} // namespace

double EdgeField::intensity(const geo::Point &p) const
{
    return sampleBilinear(smooth, p.x(), p.y());
}
geo::Point EdgeField::gradient(const geo::Point &p) const
{
    return {sampleBilinear(gx, p.x(), p.y()), sampleBilinear(gy, p.x(), p.y())};
}

EdgeField edgeField(const cv::Mat &gray, double sigmaPx)
{
    EdgeField f;
    gray.convertTo(f.smooth, CV_32F);
    if (sigmaPx > 0.0)
        cv::GaussianBlur(f.smooth, f.smooth, cv::Size(), sigmaPx);
    // Scharr's kernel: the most rotation-invariant 3×3 derivative; /32 gives intensity per pixel.
    cv::Scharr(f.smooth, f.gx, CV_32F, 1, 0, 1.0 / 32.0);
    cv::Scharr(f.smooth, f.gy, CV_32F, 0, 1, 1.0 / 32.0);
    return f;
}

namespace {

// The background's brightness over the image, a quadratic in x and y (vignetting, uneven light), fitted
// to a small copy: first to the image's border band (background by assumption), then again to every
// pixel within 2.5 robust deviations of that fit, twice. Returns the background at full size (CV_32F).
cv::Mat backgroundField(const cv::Mat &gray)
{
    const double f = std::min(1.0, 160.0 / std::max(gray.cols, gray.rows));
    cv::Mat small;
    cv::resize(gray, small, cv::Size(), f, f, cv::INTER_AREA);
    const int w = small.cols, h = small.rows, band = std::max(2, std::min(w, h) / 20);
    const auto basis = [&](int x, int y) {
        const double u = 2.0 * x / w - 1.0, v = 2.0 * y / h - 1.0;
        return Eigen::Matrix<double, 6, 1>(1.0, u, v, u * u, u * v, v * v);
    };
    Eigen::Matrix<double, 6, 1> coef = Eigen::Matrix<double, 6, 1>::Zero();
    double spread = 0.0;
    for (int round = 0; round < 3; ++round) {
        Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
        Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
        std::vector<double> residuals;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const bool border = x < band || y < band || x >= w - band || y >= h - band;
                const auto b = basis(x, y);
                const double value = small.at<std::uint8_t>(y, x);
                if (round == 0 ? !border : std::abs(value - b.dot(coef)) > 2.5 * spread)
                    continue;
                normal += b * b.transpose();
                rhs += b * value;
            }
        coef = normal.ldlt().solve(rhs);
        for (int y = 0; y < h; y += 2)
            for (int x = 0; x < w; x += 2)
                if (x < band || y < band || x >= w - band || y >= h - band)
                    residuals.push_back(std::abs(small.at<std::uint8_t>(y, x) - basis(x, y).dot(coef)));
        std::nth_element(residuals.begin(), residuals.begin() + static_cast<std::ptrdiff_t>(residuals.size() / 2),
                         residuals.end());
        spread = std::max(2.0, 1.4826 * residuals[residuals.size() / 2]);
    }
    cv::Mat bg(small.size(), CV_32F);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            bg.at<float>(y, x) = static_cast<float>(basis(x, y).dot(coef));
    cv::resize(bg, bg, gray.size(), 0, 0, cv::INTER_LINEAR);
    return bg;
}

} // namespace

std::vector<Region> segmentPieces(const cv::Mat &gray, double minAreaPx, double closeRadiusPx,
                                  const std::optional<std::vector<geo::Point>> &ignore)
{
    // The pieces are what differs from the background, brighter or darker: smooth away the table's
    // texture and the paper's grain, subtract the background's brightness, and split the size of the
    // difference in two by Otsu's threshold (Otsu 1979).
    cv::Mat smooth, diff, mask;
    const double sigma = std::max(2.0, std::min(gray.cols, gray.rows) / 800.0);
    cv::GaussianBlur(gray, smooth, cv::Size(), sigma);
    smooth.convertTo(diff, CV_32F);
    diff -= backgroundField(gray);
    cv::Mat magnitude;
    cv::absdiff(diff, cv::Scalar(0), magnitude);
    magnitude.convertTo(magnitude, CV_8U);
    cv::threshold(magnitude, mask, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU);
    if (closeRadiusPx >= 1.0) {
        const int r = static_cast<int>(std::lround(closeRadiusPx));
        cv::morphologyEx(mask, mask, cv::MORPH_CLOSE,
                         cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * r + 1, 2 * r + 1}));
    }
    mask.row(0).setTo(0), mask.row(mask.rows - 1).setTo(0), mask.col(0).setTo(0), mask.col(mask.cols - 1).setTo(0);

    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
    double ignoreArea = 0.0;
    geo::Point ignoreCentre = geo::Point::Zero();
    if (ignore && ignore->size() >= 3) {
        for (std::size_t i = 0, j = ignore->size() - 1; i < ignore->size(); j = i++) {
            const double cross = (*ignore)[j].x() * (*ignore)[i].y() - (*ignore)[i].x() * (*ignore)[j].y();
            ignoreArea += 0.5 * cross;
        }
        ignoreArea = std::abs(ignoreArea);
        for (const auto &p : *ignore)
            ignoreCentre += p / static_cast<double>(ignore->size());
    }
    std::vector<Region> regions;
    for (auto &c : contours) {
        const double area = std::abs(signedArea(c));
        if (area < minAreaPx || c.size() < 16)
            continue;
        const cv::Moments m = cv::moments(c);
        const geo::Point centre(m.m10 / m.m00, m.m01 / m.m00);
        if (ignoreArea > 0.0 && std::abs(area - ignoreArea) < 0.08 * ignoreArea &&
            (centre - ignoreCentre).norm() < 0.05 * std::sqrt(ignoreArea))
            continue;
        Region r;
        r.area = area;
        // A piece drawn as a line: its own pixels fill a small part of what its outline encloses.
        // Brighter or darker than the background: the sign of its pixels' mean difference.
        const cv::Rect box = cv::boundingRect(c);
        cv::Mat filled(box.size(), CV_8U, cv::Scalar(0));
        cv::drawContours(filled, std::vector<std::vector<cv::Point>>{c}, 0, cv::Scalar(255), cv::FILLED, cv::LINE_8,
                         cv::noArray(), 0, -box.tl());
        const cv::Mat own = mask(box) & filled;
        r.drawn = cv::countNonZero(own) < 0.35 * area;
        r.polarity = cv::mean(diff(box), own)[0] >= 0.0 ? 1 : -1;
        r.contour = std::move(c);
        regions.push_back(std::move(r));
    }
    std::sort(regions.begin(), regions.end(), [](const Region &a, const Region &b) { return a.area > b.area; });
    return regions;
}

std::optional<EdgeHit> edgeAlong(const EdgeField &field, const geo::Point &p, const geo::Point &n, double radius,
                                 int polarity, bool ridge)
{
    constexpr double h = 0.5; // samples per pixel: two, enough for a parabola on a blurred edge
    const int k = std::max(2, static_cast<int>(std::ceil(radius / h)));
    std::vector<double> d(static_cast<std::size_t>(2 * k + 1));
    for (int i = -k; i <= k; ++i) {
        const geo::Point q = p + (i * h) * n;
        d[static_cast<std::size_t>(i + k)] =
            ridge ? polarity * field.intensity(q) : -polarity * field.gradient(q).dot(n);
    }
    const auto best = std::max_element(d.begin(), d.end());
    const auto i = static_cast<int>(best - d.begin());
    if (i == 0 || i == 2 * k)
        return std::nullopt;
    const double a = d[static_cast<std::size_t>(i - 1)], b = *best, c = d[static_cast<std::size_t>(i + 1)];
    const double curvature = a - 2 * b + c;
    const double shift = curvature < 0.0 ? 0.5 * (a - c) / curvature : 0.0;
    EdgeHit hit;
    hit.t = (i - k + std::clamp(shift, -0.5, 0.5)) * h;
    // For a line, the strength is its depth below the lower of the two ends of the search.
    hit.strength = ridge ? b - std::max(d.front(), d.back()) : b;
    return hit;
}

namespace {

constexpr double kLineContrastShare = 0.25;
constexpr double kLineCandidateShare = 0.125;

// The extremum of sign·(derivative along n) for t in [from, to], sub-pixel by a parabola (Devernay 1995).
std::optional<EdgeHit> steepest(const EdgeField &field, const geo::Point &p, const geo::Point &n, double sign,
                                double from, double to)
{
    constexpr double h = 0.5;
    const auto slope = [&](double t) { return sign * field.gradient(p + t * n).dot(n); };
    double best = from, bestSlope = -std::numeric_limits<double>::infinity();
    for (double t = from; t <= to; t += h)
        if (const double g = slope(t); g > bestSlope)
            bestSlope = g, best = t;
    if (!(bestSlope > 0.0))
        return std::nullopt;
    const double a = slope(best - h), c = slope(best + h);
    const double curvature = a - 2 * bestSlope + c;
    const double shift = curvature < 0.0 ? std::clamp(0.5 * (a - c) / curvature, -0.5, 0.5) : 0.0;
    return EdgeHit{best + shift * h, bestSlope};
}

} // namespace

PaperEdge paperEdge(const EdgeField &field, const geo::Point &p, const geo::Point &n, double paperLevel, double reachPx)
{
    constexpr double h = 0.5;
    PaperEdge out;
    std::array<double, 5> far{};
    for (std::size_t i = 0; i < far.size(); ++i)
        far[i] = field.intensity(p + (reachPx + static_cast<double>(i)) * n);
    std::nth_element(far.begin(), far.begin() + 2, far.end());
    out.table = far[2];
    const double contrast = paperLevel - out.table;
    if (!(contrast > kMinPaperContrast))
        return out;
    // From the table inwards: the first sample brighter than the table by half the contrast, the
    // middle of a blurred step (the search for its steepest point about it is then centred).
    std::optional<double> paper;
    for (double t = reachPx; t >= -reachPx; t -= h)
        if (field.intensity(p + t * n) > out.table + contrast / 2.0) {
            paper = t;
            break;
        }
    if (!paper)
        return out;
    // A line on the edge begins at the paper's step: its darkest point within half the reach of it
    // (farther out, a dark fleck of the table).
    double darkest = out.table, darkestT = reachPx;
    for (double t = *paper; t <= std::min(reachPx, *paper + 0.5 * reachPx); t += h)
        if (const double v = field.intensity(p + t * n); v < darkest)
            darkest = v, darkestT = t;
    out.bright = steepest(field, p, n, -1.0, *paper - 1.5, *paper + 1.5);
    // A band darker than the table between the paper and the table: its outer side, where it rises
    // back to the table (searched to where it is within half the depth of the table, and 1.5 px on).
    out.darkDepth = out.table - darkest;
    if (out.bright && out.darkDepth > 0.0) {
        double to = darkestT;
        while (to < reachPx && field.intensity(p + to * n) < out.table - 0.5 * (out.table - darkest))
            to += h;
        out.dark = steepest(field, p, n, 1.0, darkestT, to + 1.5);
    }
    return out;
}

namespace {

// The outer side of a band darker than `table` by half of `depth` or more along p + t·n, |t| <=
// reachPx, seen from the table (t = reachPx) inwards: the rising step back to the table about the first
// sample that dark.
std::optional<EdgeHit> bandOuterSide(const EdgeField &field, const geo::Point &p, const geo::Point &n, double table,
                                     double depth, double reachPx)
{
    constexpr double h = 0.5;
    for (double t = reachPx; t >= -reachPx; t -= h)
        if (field.intensity(p + t * n) < table - 0.5 * depth)
            return steepest(field, p, n, 1.0, t - 1.5, t + 1.5);
    return std::nullopt;
}

// A bright fleck of the table within the reach is not the paper's edge: a point more than 1.5 px off
// the median of its 13 neighbours' offsets is dropped (the list is a closed loop).
void dropOffMedian(std::vector<std::optional<EdgeHit>> &hits)
{
    const std::size_t count = hits.size();
    std::vector<double> offset(count, std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i = 0; i < count; ++i)
        if (hits[i])
            offset[i] = hits[i]->t;
    std::vector<double> near;
    for (std::size_t i = 0; i < count; ++i) {
        if (std::isnan(offset[i]))
            continue;
        near.clear();
        for (std::size_t k = count + i - 6; k <= count + i + 6; ++k)
            if (!std::isnan(offset[k % count]))
                near.push_back(offset[k % count]);
        std::nth_element(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(near.size() / 2), near.end());
        if (std::abs(offset[i] - near[near.size() / 2]) > 1.5)
            hits[i].reset();
    }
}

// The points p + t·out of the hits, without those weaker than a third of the median hit.
std::vector<geo::Point> strongEnough(const std::vector<geo::Point> &p, const std::vector<geo::Point> &out,
                                     const std::vector<std::optional<EdgeHit>> &hits)
{
    std::vector<geo::Point> pts;
    std::vector<double> strength;
    for (std::size_t i = 0; i < hits.size(); ++i)
        if (hits[i]) {
            pts.push_back(p[i] + hits[i]->t * out[i]);
            strength.push_back(hits[i]->strength);
        }
    if (pts.empty())
        return pts;
    std::vector<double> sorted = strength;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
    const double floor = sorted[sorted.size() / 2] / 3.0;
    std::vector<geo::Point> kept;
    kept.reserve(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i)
        if (strength[i] >= floor)
            kept.push_back(pts[i]);
    return kept;
}

// A point of the segmented contour: where it is, its outward normal and the strongest step along it.
struct Sample
{
    geo::Point p, out;
    std::optional<EdgeHit> hit;
};

// A line on the paper's edge (lineband.h), from the profiles across it, each aligned at its
// paper-to-line step, where the band is at least half as deep as the line's median.
std::optional<LineBand> edgeLineBand(const EdgeField &field, const std::vector<Sample> &samples,
                                    const std::vector<PaperEdge> &edges, double lineDepth, double paper, double table,
                                    double reachPx)
{
    MeanProfile profile;
    profile.from = -4.0;
    const auto count = static_cast<std::size_t>((0.5 * reachPx + 8.0) / profile.step) + 1;
    profile.value.assign(count, 0.0);
    int used = 0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const PaperEdge &e = edges[i];
        if (!e.bright || !e.dark || !(e.darkDepth > 0.5 * lineDepth))
            continue;
        for (std::size_t k = 0; k < count; ++k)
            profile.value[k] += field.intensity(samples[i].p + (e.bright->t + profile.from +
                                                                static_cast<double>(k) * profile.step) *
                                                                   samples[i].out);
        ++used;
    }
    if (used < 20)
        return std::nullopt;
    for (double &v : profile.value)
        v /= used;
    return fitLineBand(profile, paper, table, kLineContrastShare * (paper - table));
}

// The paper's edge `width` px beyond a line's inner side (the paper's step found).
EdgeHit beyondInnerSide(const PaperEdge &e, double width)
{
    return EdgeHit{e.bright->t + width, e.bright->strength};
}

// The paper's edge where a line lies on it (`line` from the first look): the line's outer step, less how
// far the blur moved it; where that step is not where the line's width puts it (a dark fleck of the
// table beyond a faint line, off by more than the line's width or 1.5 px), the line's inner side moved
// out by that width.
EdgeHit onLine(const PaperEdge &e, const ContourEdge &line)
{
    if (!line.lineOuter)
        return *e.dark;
    const double expected = *line.lineOuter + line.riseShift;
    if (std::abs(e.dark->t - e.bright->t - expected) <= std::max(1.5, *line.lineOuter))
        return EdgeHit{e.dark->t - line.riseShift, e.dark->strength};
    return beyondInnerSide(e, *line.lineOuter);
}

} // namespace

ContourEdge subpixelContour(const EdgeField &field, const Region &region, double radius, double lineReachPx)
{
    ContourEdge result;
    const auto &c = region.contour;
    const int n = static_cast<int>(c.size());
    // With a positive signed area the inside lies to the left of the direction of travel.
    const double orient = signedArea(c) > 0.0 ? 1.0 : -1.0;
    const int m = 3; // the tangent from the points 3 apart on either side: a few pixels of contour
    std::vector<Sample> samples;
    samples.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        const cv::Point a = c[static_cast<std::size_t>((i + n - m) % n)], b = c[static_cast<std::size_t>((i + m) % n)];
        geo::Point t(b.x - a.x, b.y - a.y);
        if (t.norm() == 0.0)
            continue;
        t.normalize();
        const geo::Point out = orient * geo::Point(t.y(), -t.x());
        const geo::Point p(c[static_cast<std::size_t>(i)].x, c[static_cast<std::size_t>(i)].y);
        samples.push_back({p, out, edgeAlong(field, p, out, radius, region.polarity, region.drawn)});
    }
    // A paper piece brighter than the table: where a dark line runs along its edge (a printed pattern
    // cut out along its line), the segmentation and the strongest step may be the line's inner side.
    // When the paper's outer edge lies beyond the step found (or where none was) at half of the outline
    // or more, the outline is the paper's edge; a few such places alone are the table's grain beside a
    // plain edge.
    std::vector<std::optional<EdgeHit>> outer(samples.size());
    bool used = false;
    if (lineReachPx > 0.0 && region.polarity > 0 && !region.drawn && !samples.empty()) {
        std::vector<double> paper;
        paper.reserve(samples.size());
        for (const Sample &s : samples)
            paper.push_back(field.intensity(s.p - (lineReachPx + 2.0) * s.out));
        std::nth_element(paper.begin(), paper.begin() + static_cast<std::ptrdiff_t>(paper.size() / 2), paper.end());
        const double paperLevel = paper[paper.size() / 2];
        std::vector<PaperEdge> edges;
        edges.reserve(samples.size());
        for (const Sample &s : samples)
            edges.push_back(paperEdge(field, s.p, s.out, paperLevel, lineReachPx));
        // A dark line along the edge: the dark band's median depth beyond the paper's edge is a quarter
        // of the paper-to-table contrast or more (the table's grain alone gives a tenth or less), and a
        // point has it where its band is at least half that deep.
        std::vector<double> depths;
        for (const PaperEdge &e : edges)
            if (e.bright)
                depths.push_back(e.darkDepth);
        if (2 * depths.size() >= samples.size()) {
            std::nth_element(depths.begin(), depths.begin() + static_cast<std::ptrdiff_t>(depths.size() / 2),
                             depths.end());
            const double lineDepth = depths[depths.size() / 2];
            const double table = field.intensity(samples.front().p + (lineReachPx + 2.0) * samples.front().out);
            // A line as narrow as the blur (0.3 mm at 8 px/mm) keeps a third of its depth, 14 % of the
            // contrast on white paper: from an eighth of the contrast on, the line model (lineband.h)
            // decides, by the depth of the line it fits; the table's grain gives no such line.
            const double contrast = paperLevel - table;
            std::optional<LineBand> band;
            if (lineDepth > std::max(kMinPaperContrast, kLineCandidateShare * contrast))
                band = edgeLineBand(field, samples, edges, lineDepth, paperLevel, table, lineReachPx);
            const bool line = band || lineDepth > std::max(kMinPaperContrast, kLineContrastShare * contrast);
            result.paperLevel = paperLevel;
            result.lineDepth = line ? lineDepth : 0.0;
            result.riseShift = band ? band->riseShift : 0.0;
            if (band)
                result.lineOuter = band->outer;
            // Elsewhere the strongest step stays the edge unless the paper goes on beyond it by more
            // than a pixel along a stretch (a strip of paper outside a line, cut off by the
            // segmentation): at 10 or more of the 13 points about it.
            const std::size_t count = edges.size();
            std::vector<char> goesOn(count);
            for (std::size_t i = 0; i < count; ++i)
                goesOn[i] = edges[i].bright && (!samples[i].hit || edges[i].bright->t > samples[i].hit->t + 1.0);
            std::size_t beyond = 0;
            for (std::size_t i = 0; i < count; ++i) {
                int around = 0;
                for (std::size_t k = count + i - 6; k <= count + i + 6; ++k)
                    around += goesOn[k % count];
                if (line && edges[i].dark && edges[i].darkDepth > 0.5 * lineDepth)
                    outer[i] = onLine(edges[i], result), ++beyond;
                else if (goesOn[i] && around >= 10)
                    outer[i] = edges[i].bright, ++beyond;
                else if (band && edges[i].bright) // a stretch where the line shows faintly
                    outer[i] = beyondInnerSide(edges[i], band->outer), ++beyond;
                else
                    outer[i] = samples[i].hit;
            }
            result.beyondLine = 2 * beyond >= count;
            dropOffMedian(outer);
            used = true;
        }
    }
    std::vector<geo::Point> p, out;
    std::vector<std::optional<EdgeHit>> hits;
    for (std::size_t i = 0; i < samples.size(); ++i)
        p.push_back(samples[i].p), out.push_back(samples[i].out), hits.push_back(used ? outer[i] : samples[i].hit);
    result.points = strongEnough(p, out, hits);
    return result;
}

std::vector<geo::Point> paperEdgeAlong(const EdgeField &field, const std::vector<geo::Point> &p,
                                       const std::vector<geo::Point> &out, const ContourEdge &first, double reachPx)
{
    std::vector<std::optional<EdgeHit>> hits;
    hits.reserve(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
        const PaperEdge e = paperEdge(field, p[i], out[i], first.paperLevel, reachPx);
        if (first.lineDepth <= 0.0)
            hits.push_back(e.bright);
        else if (e.bright && e.dark && e.darkDepth > 0.5 * first.lineDepth)
            hits.push_back(onLine(e, first));
        else if (e.bright)
            hits.push_back(first.lineOuter ? beyondInnerSide(e, *first.lineOuter) : e.bright);
        else // near a sharp tip the lines along its two sides merge and no paper shows between them
            hits.push_back(bandOuterSide(field, p[i], out[i], e.table, first.lineDepth, reachPx));
    }
    dropOffMedian(hits);
    return strongEnough(p, out, hits);
}

} // namespace kontur::vision::detail
