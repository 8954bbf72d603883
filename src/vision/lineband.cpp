// The width of a line on the paper's edge from the outline's mean profile (lineband.h).
#include "vision/lineband.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace kontur::vision::detail {

namespace {

// The parameters in the order P, L, T, a, e, s.
using Params = Eigen::Matrix<double, 6, 1>;

double cdf(double z)
{
    return 0.5 * std::erfc(-z / std::numbers::sqrt2);
}
double pdf(double z)
{
    return std::exp(-0.5 * z * z) / std::sqrt(2.0 * std::numbers::pi);
}

double model(const Params &q, double u)
{
    return q[0] + (q[1] - q[0]) * cdf((u - q[3]) / q[5]) + (q[2] - q[1]) * cdf((u - q[4]) / q[5]);
}

Eigen::Matrix<double, 1, 6> jacobianRow(const Params &q, double u)
{
    const double s = q[5], za = (u - q[3]) / s, ze = (u - q[4]) / s;
    const double fa = cdf(za), fe = cdf(ze), ga = pdf(za), ge = pdf(ze);
    const double inner = q[1] - q[0], outer = q[2] - q[1];
    Eigen::Matrix<double, 1, 6> row;
    row << 1.0 - fa, fa - fe, fe, -inner * ga / s, -outer * ge / s, -(inner * ga * za + outer * ge * ze) / s;
    return row;
}

double cost(const Params &q, const MeanProfile &profile)
{
    double sum = 0.0;
    for (std::size_t i = 0; i < profile.value.size(); ++i) {
        const double r = model(q, profile.from + static_cast<double>(i) * profile.step) - profile.value[i];
        sum += r * r;
    }
    return sum;
}

bool plausible(const Params &q, double end)
{
    return q[5] > 0.2 && q[5] < 6.0 && q[4] > q[3] && q[4] < end && std::abs(q[3]) < 2.0;
}

} // namespace

std::optional<LineBand> fitLineBand(const MeanProfile &profile, double paper, double table, double minDepth)
{
    const auto n = profile.value.size();
    if (n < 8 || !(profile.step > 0.0))
        return std::nullopt;
    const double end = profile.from + static_cast<double>(n - 1) * profile.step;
    // Start from the line's darkest sample: its middle there, its level that sample's.
    const auto darkest = std::min_element(profile.value.begin(), profile.value.end());
    const double middle = profile.from + static_cast<double>(darkest - profile.value.begin()) * profile.step;
    Params q;
    q << paper, *darkest, table, 0.0, std::max(1.0, 2.0 * middle), 1.2;
    double c = cost(q, profile), lambda = 1e-2;
    for (int iteration = 0; iteration < 200; ++iteration) {
        Eigen::Matrix<double, 6, 6> jtj = Eigen::Matrix<double, 6, 6>::Zero();
        Params jtr = Params::Zero();
        for (std::size_t i = 0; i < n; ++i) {
            const double u = profile.from + static_cast<double>(i) * profile.step;
            const auto row = jacobianRow(q, u);
            jtj += row.transpose() * row;
            jtr += row.transpose() * (model(q, u) - profile.value[i]);
        }
        Eigen::Matrix<double, 6, 6> damped = jtj;
        damped.diagonal() += lambda * jtj.diagonal().cwiseMax(1e-9);
        const Params next = q - damped.ldlt().solve(jtr);
        const double nextCost = plausible(next, end) ? cost(next, profile) : std::numeric_limits<double>::infinity();
        if (nextCost < c) {
            const bool settled = (next - q).cwiseAbs().maxCoeff() < 1e-6;
            q = next, c = nextCost, lambda = std::max(1e-9, lambda / 3.0);
            if (settled)
                break;
        } else {
            lambda *= 4.0;
            if (lambda > 1e9)
                break;
        }
    }
    const double depth = q[2] - q[1], width = q[4] - q[3];
    if (!plausible(q, end) || !(depth >= minDepth) || !(width >= 0.5))
        return std::nullopt;
    // The steepest rise of the model about e, to a hundredth of a pixel.
    double rise = q[4], steepest = -std::numeric_limits<double>::infinity();
    for (double u = q[4] - 2.0 * q[5]; u <= q[4] + 3.0 * q[5]; u += 0.01) {
        const double slope = model(q, u + 0.005) - model(q, u - 0.005);
        if (slope > steepest)
            steepest = slope, rise = u;
    }
    return LineBand{q[4], rise - q[4], q[5]};
}

} // namespace kontur::vision::detail
