#pragma once
// Plain byte packing of arrays, for results that cross from a worker process (isolation.h).
// Same machine, same build on both ends: no byte-order or versioning concerns.
#include <cstring>
#include <string>
#include <type_traits>

#include <Eigen/Core>

#include "framefix/core/error.h"

namespace framefix {

class ByteWriter {
public:
    template <class T>
    void value(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes_.append(reinterpret_cast<const char*>(&v), sizeof v);
    }
    template <class Derived>
    void matrix(const Eigen::PlainObjectBase<Derived>& m) {
        value<Eigen::Index>(m.rows());
        value<Eigen::Index>(m.cols());
        bytes_.append(reinterpret_cast<const char*>(m.data()), size_t(m.size()) * sizeof(typename Derived::Scalar));
    }
    void text(const std::string& s) {
        value<size_t>(s.size());
        bytes_.append(s);
    }
    std::string take() { return std::move(bytes_); }

private:
    std::string bytes_;
};

class ByteReader {
public:
    explicit ByteReader(const std::string& bytes) : bytes_(bytes) {}
    template <class T>
    T value() {
        T v;
        std::memcpy(&v, take(sizeof v), sizeof v);
        return v;
    }
    template <class Derived>
    void matrix(Eigen::PlainObjectBase<Derived>& m) {
        const auto rows = value<Eigen::Index>(), cols = value<Eigen::Index>();
        m.resize(rows, cols);
        const size_t n = size_t(m.size()) * sizeof(typename Derived::Scalar);
        if (n) std::memcpy(m.data(), take(n), n);
    }
    std::string text() {
        const auto n = value<size_t>();
        return std::string(take(n), n);
    }
    bool done() const { return at_ == bytes_.size(); }

private:
    const char* take(size_t n) {
        if (n > bytes_.size() - at_) throw InternalError("ByteReader: truncated worker result");
        const char* p = bytes_.data() + at_;
        at_ += n;
        return p;
    }
    const std::string& bytes_;
    size_t at_ = 0;
};

}  // namespace framefix
