// Scalar Bernstein polynomials on [0, 1] and their real roots (see bernstein.h).
#include "geometry/bernstein.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace kontur::geo {

double binomial(int n, int k)
{
    if (k < 0 || k > n)
        return 0.0;
    k = std::min(k, n - k);
    double r = 1.0;
    for (int i = 1; i <= k; ++i)
        r = r * (n - k + i) / i;
    // Each partial product is itself a binomial coefficient, so r stays exact below 2^53.
    return r;
}

namespace {

// de Casteljau on n coefficients (n >= 1) in a caller's scratch buffer; p'(t) from the last level.
double evalInto(const double *b, std::size_t n, double t, double *w, double *derivative)
{
    for (std::size_t i = 0; i < n; ++i)
        w[i] = b[i];
    if (n == 1) {
        if (derivative)
            *derivative = 0.0;
        return w[0];
    }
    const double s = 1.0 - t;
    for (std::size_t level = n - 1; level > 1; --level)
        for (std::size_t i = 0; i < level; ++i)
            w[i] = s * w[i] + t * w[i + 1];
    if (derivative)
        *derivative = static_cast<double>(n - 1) * (w[1] - w[0]);
    return s * w[0] + t * w[1];
}

} // namespace

double bernsteinEval(std::span<const double> b, double t, double *derivative)
{
    const std::size_t n = b.size();
    if (n == 0) {
        if (derivative)
            *derivative = 0.0;
        return 0.0;
    }
    std::array<double, 64> local;
    if (n <= local.size())
        return evalInto(b.data(), n, t, local.data(), derivative);
    std::vector<double> heap(n);
    return evalInto(b.data(), n, t, heap.data(), derivative);
}

std::vector<double> bernsteinDerivative(std::span<const double> b)
{
    if (b.size() < 2)
        return {};
    const double n = static_cast<double>(b.size() - 1);
    std::vector<double> d(b.size() - 1);
    for (std::size_t i = 0; i + 1 < b.size(); ++i)
        d[i] = n * (b[i + 1] - b[i]);
    return d;
}

std::vector<double> bernsteinProduct(std::span<const double> p, std::span<const double> q)
{
    if (p.empty() || q.empty())
        return {};
    const int n = static_cast<int>(p.size()) - 1;
    const int m = static_cast<int>(q.size()) - 1;
    std::vector<double> r(n + m + 1, 0.0);
    // C(n,i) C(m,j) / C(n+m,i+j): the Bernstein product rule (Farouki & Rajan 1988).
    if (n + m <= 1000) {
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= m; ++j)
                r[i + j] += binomial(n, i) * binomial(m, j) * p[i] * q[j];
        for (int k = 0; k <= n + m; ++k)
            r[k] /= binomial(n + m, k);
        return r;
    }
    // Beyond, C(n+m, k) overflows a double: the weight from logarithms (a hypergeometric
    // probability, at most 1, so the exponential cannot overflow).
    auto lc = [](int a, int b) { return std::lgamma(a + 1.0) - std::lgamma(b + 1.0) - std::lgamma(a - b + 1.0); };
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= m; ++j)
            r[i + j] += std::exp(lc(n, i) + lc(m, j) - lc(n + m, i + j)) * p[i] * q[j];
    return r;
}

namespace {

// Scratch space for one polynomial of the recursion: its coefficients and de Casteljau work.
// Degrees up to kInline - 1 run without touching the heap (a cubic's nearest point is degree 5).
constexpr std::size_t kInline = 32;

struct Poly
{
    const double *b;
    std::size_t n; // number of coefficients
    double *work;  // n doubles
    double eval(double t, double *d = nullptr) const { return evalInto(b, n, t, work, d); }
};

// The root of p in [lo, hi] where p(lo) and p(hi) have opposite signs and p is monotone:
// Newton steps kept inside a shrinking bracket, bisection when a step would leave it.
double refineRoot(const Poly &p, double lo, double hi, double flo)
{
    double t = 0.5 * (lo + hi);
    for (int iter = 0; iter < 100; ++iter) {
        double d = 0.0;
        const double f = p.eval(t, &d);
        if (f == 0.0)
            return t;
        if ((f < 0.0) == (flo < 0.0))
            lo = t;
        else
            hi = t;
        double next = d != 0.0 ? t - f / d : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) // also catches NaN
            next = 0.5 * (lo + hi);
        if (std::abs(next - t) <= 2.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(t)) ||
            hi - lo <= 4.0 * std::numeric_limits<double>::epsilon())
            return next;
        t = next;
    }
    return t;
}

// A vector that lives on the stack for the degrees Kontur meets; heap only beyond.
class SmallVector
{
public:
    void push_back(double v)
    {
        if (m_heap.empty() && m_size < m_local.size()) {
            m_local[m_size++] = v;
            return;
        }
        if (m_heap.empty())
            m_heap.assign(m_local.begin(), m_local.begin() + static_cast<std::ptrdiff_t>(m_size));
        m_heap.push_back(v);
        ++m_size;
    }
    [[nodiscard]] bool empty() const { return m_size == 0; }
    [[nodiscard]] std::size_t size() const { return m_size; }
    [[nodiscard]] const double *data() const { return m_heap.empty() ? m_local.data() : m_heap.data(); }
    [[nodiscard]] double back() const { return data()[m_size - 1]; }

private:
    std::array<double, kInline + 2> m_local;
    std::vector<double> m_heap;
    std::size_t m_size = 0;
};

// Appends the roots in [0, 1] in increasing order (possibly with a repeated value at a break).
void rootsRecursive(const double *b, std::size_t size, SmallVector &out, bool risingOnly)
{
    if (size < 2)
        return;
    bool allZero = true;
    for (std::size_t i = 0; i < size; ++i)
        allZero = allZero && b[i] == 0.0;
    if (allZero)
        return;
    std::array<double, kInline> derivLocal, workLocal;
    std::vector<double> derivHeap, workHeap;
    double *deriv = derivLocal.data();
    double *work = workLocal.data();
    if (size > kInline) {
        derivHeap.resize(size);
        workHeap.resize(size);
        deriv = derivHeap.data();
        work = workHeap.data();
    }
    // Break points: 0, the roots of p' (where p turns), 1. Between them p is monotone.
    SmallVector breaks;
    breaks.push_back(0.0);
    if (size > 2) {
        const double n = static_cast<double>(size - 1);
        for (std::size_t i = 0; i + 1 < size; ++i)
            deriv[i] = n * (b[i + 1] - b[i]);
        rootsRecursive(deriv, size - 1, breaks, false);
    }
    breaks.push_back(1.0);
    const std::size_t breakCount = breaks.size();
    const Poly p{b, size, work};
    double prevT = 0.0;
    double prevF = b[0];
    if (prevF == 0.0 && !risingOnly)
        out.push_back(0.0);
    for (std::size_t k = 1; k < breakCount; ++k) {
        const double t = breaks.data()[k];
        const bool last = k + 1 == breakCount;
        if (t <= prevT && !last)
            continue;
        const double f = last ? b[size - 1] : p.eval(t);
        if (f == 0.0) {
            if ((!risingOnly || prevF < 0.0) && (out.empty() || out.back() != t))
                out.push_back(t);
        } else if (prevF != 0.0 && (prevF < 0.0) != (f < 0.0)) {
            if (!risingOnly || prevF < 0.0) {
                if (size == 2) // linear: the root in closed form
                    out.push_back(std::clamp(b[0] / (b[0] - b[1]), prevT, t));
                else
                    out.push_back(refineRoot(p, prevT, t, prevF));
            }
        }
        prevT = t;
        prevF = f;
    }
}

} // namespace

void bernsteinRoots(std::span<const double> b, std::vector<double> &roots, bool risingOnly)
{
    const std::size_t first = roots.size();
    SmallVector found;
    rootsRecursive(b.data(), b.size(), found, risingOnly);
    roots.insert(roots.end(), found.data(), found.data() + found.size());
    std::sort(roots.begin() + static_cast<std::ptrdiff_t>(first), roots.end());
    roots.erase(std::unique(roots.begin() + static_cast<std::ptrdiff_t>(first), roots.end()), roots.end());
}

} // namespace kontur::geo
