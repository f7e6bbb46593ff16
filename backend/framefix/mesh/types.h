#pragma once
// Plain array types shared by every module: row-major so numpy sees them without copies.
#include <Eigen/Core>

namespace framefix {

using Points = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;     // #P x 3, model units
using Triangles = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;     // #F x 3 point indices
using Tets = Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor>;          // #T x 4 point indices
using Segments = Eigen::Matrix<int, Eigen::Dynamic, 2, Eigen::RowMajor>;      // #S x 2 point indices

}  // namespace framefix
