#pragma once
// PROVISIONAL (replaced by the hygiene branch's size model at merge).
namespace framefix {
constexpr int kDefaultTargetTets = 50000;
constexpr double kMeanTetVolumePerH3 = 0.085;
}  // namespace framefix
