#include "models/eigen_decompositions.h"

template class Eigen::JacobiSVD<Eigen::MatrixXd>;
template class Eigen::JacobiSVD<Eigen::Matrix3d>;
template class Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>;
template class Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>>;
template class Eigen::LLT<Eigen::MatrixXd>;
template class Eigen::HouseholderQR<Eigen::MatrixXd>;
template class Eigen::ColPivHouseholderQR<Eigen::MatrixXd>;
template class Eigen::PartialPivLU<Eigen::MatrixXd>;
