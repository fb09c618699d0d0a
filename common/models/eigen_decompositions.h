// Eigen's dense decompositions of dynamic size that the library uses,
// compiled once (eigen_decompositions.cpp) instead of in every file that
// uses one: each is some 10 to 40 s of that file's compile. Include this
// instead of <Eigen/Dense> where one of them is used; the instances are in
// the core layer, which every other layer builds on.
#pragma once

#include <Eigen/Dense>

extern template class Eigen::JacobiSVD<Eigen::MatrixXd>;
extern template class Eigen::JacobiSVD<Eigen::Matrix3d>;
extern template class Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>;
extern template class Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>>;
extern template class Eigen::LLT<Eigen::MatrixXd>;
extern template class Eigen::HouseholderQR<Eigen::MatrixXd>;
extern template class Eigen::ColPivHouseholderQR<Eigen::MatrixXd>;
extern template class Eigen::PartialPivLU<Eigen::MatrixXd>;
