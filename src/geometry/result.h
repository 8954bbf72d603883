// A small typed result for operations that can fail on degenerate input (the library never throws
// across its boundary and never answers NaN): either a value or an error code with a message.
#pragma once

#include <string>
#include <utility>
#include <variant>

namespace kontur::geo {

enum class ErrorCode {
    TooFewPoints,             // fewer points than the operation needs
    AllPointsEqual,           // every input point is the same point
    CoincidentPoints,         // two consecutive input points coincide
    TooFewDistinctParameters, // fewer than 4 distinct parameter values for a cubic fit
    IllConditioned,           // the least-squares system is numerically rank deficient
    NonFiniteInput,           // a coordinate is NaN or infinite
    IndexOutOfRange,          // a knot, handle or segment index that does not exist
    InvalidArgument,          // any other argument outside its documented range
    OutOfProportion,          // an argument out of all proportion to the input's size (an offset 1e12 × wider)
    WorkBudget,               // the input would need more work than the routine's budget allows
    Cancelled,                // another thread asked the routine to stop (see geo::OffsetControl)
};

struct Error
{
    ErrorCode code;
    std::string message; // English, for logs and the CLI; the UI maps `code` to its own strings
    int index = -1;      // the offending point or knot, when there is one
};

// std::expected is C++23; this is the part of it Kontur needs: a value or an error. The file layer
// (src/io) uses it with its own error type.
template <typename T, typename E> class [[nodiscard]] Expected final
{
public:
    Expected(T value)
        : m_data(std::in_place_index<0>, std::move(value))
    {
    }
    Expected(E error)
        : m_data(std::in_place_index<1>, std::move(error))
    {
    }

    [[nodiscard]] bool ok() const { return m_data.index() == 0; }
    explicit operator bool() const { return ok(); }
    [[nodiscard]] const T &value() const & { return std::get<0>(m_data); }
    [[nodiscard]] T &value() & { return std::get<0>(m_data); }
    [[nodiscard]] T &&value() && { return std::get<0>(std::move(m_data)); }
    const T &operator*() const & { return value(); }
    T &operator*() & { return value(); }
    const T *operator->() const { return &value(); }
    T *operator->() { return &value(); }
    [[nodiscard]] const E &error() const { return std::get<1>(m_data); }
    [[nodiscard]] E &error() { return std::get<1>(m_data); }

private:
    std::variant<T, E> m_data;
};

template <typename T> using Result = Expected<T, Error>;

// For operations with no value to return.
struct Ok
{
};

} // namespace kontur::geo
