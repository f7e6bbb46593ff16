#include <gtest/gtest.h>

#include "framefix/core/bytes.h"

namespace framefix {
namespace {

TEST(Bytes, MatricesAndValuesComeBackExactly) {
    Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> p(2, 3);
    p << 1, 2, 3, 0.1, -1e-300, 7;
    Eigen::VectorXi v(3);
    v << 4, -5, 6;
    Eigen::VectorXi empty;
    ByteWriter w;
    w.matrix(p);
    w.value(2.5);
    w.matrix(empty);
    w.matrix(v);
    const std::string bytes = w.take();
    ByteReader r(bytes);
    Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> p2;
    Eigen::VectorXi v2, e2;
    r.matrix(p2);
    EXPECT_EQ(r.value<double>(), 2.5);
    r.matrix(e2);
    r.matrix(v2);
    EXPECT_TRUE(r.done());
    EXPECT_EQ(p2, p);
    EXPECT_EQ(v2, v);
    EXPECT_EQ(e2.size(), 0);
}

TEST(Bytes, ATruncatedResultIsAnInternalError) {
    ByteWriter w;
    w.value(1.0);
    const std::string bytes = w.take().substr(0, 5);
    ByteReader r(bytes);
    EXPECT_THROW(r.value<double>(), InternalError);
}

}  // namespace
}  // namespace framefix
