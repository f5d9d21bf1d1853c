// demcontact for C++17: header-only wrapper over the C API in demcontact.h.
//
//  * namespace demcontact; strong enums `status` and `criterion`;
//  * for every status-returning C function `dc_f(args..., T *out)`, a value-returning
//    `demcontact::f(args...)` that throws demcontact::error, and a `noexcept` overload
//    `demcontact::f(args..., T& out)` that returns the status (generated, in
//    demcontact_generated.hpp, from the C header by `cargo test --test bindings`);
//  * `span`-like views for batched kernels (C++17, no <span> needed);
//  * no RAII types: the library owns nothing that would need releasing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "demcontact.h"

namespace demcontact {

enum class status : std::int32_t;

/// Message of a status (static storage).
inline const char* status_str(status s) noexcept { return ::dc_status_str(static_cast<std::int32_t>(s)); }

/// Library version string.
inline const char* version() noexcept { return ::dc_version(); }

/// The exception thrown by the value-returning wrappers; carries the C status.
class error : public std::runtime_error {
public:
    explicit error(status s) : std::runtime_error(status_str(s)), status_(s) {}
    /// The status the C function returned.
    status code() const noexcept { return status_; }

private:
    status status_;
};

namespace detail {
inline void check(std::int32_t s) {
    if (s != DC_OK) throw error(static_cast<status>(s));
}
}  // namespace detail

/// A non-owning view of contiguous elements (the C++17 stand-in for std::span).
template <class T>
class span {
public:
    constexpr span() noexcept = default;
    constexpr span(T* data, std::size_t size) noexcept : data_(data), size_(size) {}
    template <class C>
    constexpr span(C& c) noexcept : data_(c.data()), size_(c.size()) {}
    constexpr T* data() const noexcept { return data_; }
    constexpr std::size_t size() const noexcept { return size_; }
    constexpr T& operator[](std::size_t i) const noexcept { return data_[i]; }
    constexpr T* begin() const noexcept { return data_; }
    constexpr T* end() const noexcept { return data_ + size_; }

private:
    T* data_ = nullptr;
    std::size_t size_ = 0;
};

}  // namespace demcontact

#include "demcontact_generated.hpp"
