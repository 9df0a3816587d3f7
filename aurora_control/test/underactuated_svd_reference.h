// TEST REFERENCE ONLY: the underactuated 12-gain controller written the
// direct way, with Eigen matrices and the pseudo-inverse through an SVD, as
// the spec's steps 1-11 read. The product uses underactuated_law.h (closed-
// form pseudo-inverse, templated); test_underactuated.cpp checks that both
// agree.
#pragma once

#include <Eigen/Dense>
#include <cmath>

#include "aurora_sim/vehicle/ardrone2/ardrone_model.h"

namespace aurora_control {

struct SvdReferenceGains {
  // (k1, k2) per axis in the order x, y, z, phi, theta, psi.
  double k1[6] = {0.5, 0.5, 5.0, 1.0, 1.0, 1.0};
  double k2[6] = {2.0, 2.0, 2.0, 20.0, 20.0, 2.5};
};

class UnderactuatedSvdReference {
 public:
  explicit UnderactuatedSvdReference(const aurora_sim::ArdroneParams<double>& p,
                                     const SvdReferenceGains& g = SvdReferenceGains())
      : p_(p), g_(g) {
    reset();
  }

  // Internal state: desired rotor speeds, own on-board reference, and the
  // desired roll and pitch the previous call computed (Xd4, Xd5).
  void reset() {
    Wd_.setZero();
    Xr_.setZero();
    roll_d_ = pitch_d_ = 0.0;
  }

  // Xd: desired 12-state (position, yaw, rates; roll and pitch come from the
  // previous call), dXd_acc: desired accelerations (feedforward, 6), X: the
  // state, U: the command [u_phi u_theta u_zdot u_psidot]. Steps 1-11 of the spec.
  void compute(const double Xd_in[aurora_sim::kStateSize], const double dXd_acc[6],
               const double X[aurora_sim::kStateSize], double U[4]) {
    using Eigen::Matrix;
    const double pi = aurora_common::kPi;
    const aurora_sim::ArdroneParams<double>& p = p_;
    double Xd[aurora_sim::kStateSize];
    for (int i = 0; i < aurora_sim::kStateSize; ++i) Xd[i] = Xd_in[i];
    Xd[aurora_sim::kRoll] = roll_d_;
    Xd[aurora_sim::kPitch] = pitch_d_;

    // 1. Errors; angle errors wrapped as the reference does.
    double e[aurora_sim::kStateSize];
    for (int i = 0; i < aurora_sim::kStateSize; ++i) e[i] = Xd[i] - X[i];
    for (int i = aurora_sim::kRoll; i <= aurora_sim::kYaw; ++i) {
      if (std::fabs(e[i]) > pi) e[i] -= 2 * pi;
      if (e[i] < -pi) e[i] += 2 * pi;
    }
    // 2. eta_i = dXd(n+6) + k1 tanh(k2 e_n) + k3 tanh(k4 e_{n+6}).
    double eta[6];
    for (int i = 0; i < 6; ++i) {
      const double k3 = std::sqrt(4 * g_.k1[i]);
      const double k4 = std::sqrt(4 * g_.k1[i] * g_.k2[i]) / k3;
      eta[i] = dXd_acc[i] + g_.k1[i] * std::tanh(g_.k2[i] * e[i]) + k3 * std::tanh(k4 * e[i + 6]);
    }
    const double sphi = std::sin(X[aurora_sim::kRoll]), cphi = std::cos(X[aurora_sim::kRoll]);
    const double sth = std::sin(X[aurora_sim::kPitch]), cth = std::cos(X[aurora_sim::kPitch]);
    const double spsi = std::sin(X[aurora_sim::kYaw]), cpsi = std::cos(X[aurora_sim::kYaw]);
    // 3. Desired roll and pitch for the next call.
    roll_d_ = std::atan2((eta[0] * spsi - eta[1] * cpsi) * cth, eta[2] + p.g);
    pitch_d_ = std::atan2(eta[0] * cpsi + eta[1] * spsi, eta[2] + p.g);

    // 4. Dynamics matrices.
    Matrix<double, 3, 3> R;
    R << cpsi * cth, cpsi * sth * sphi - spsi * cphi, cpsi * sth * cphi + spsi * sphi,
        spsi * cth, spsi * sth * sphi + cpsi * cphi, spsi * sth * cphi - cpsi * sphi,
        -sth, cth * sphi, cth * cphi;
    double Mr_a[3][3], Cr_a[3][3];
    aurora_sim::inertiaMatrix(p, sphi, cphi, sth, cth, Mr_a);
    aurora_sim::coriolisMatrix(p, sphi, cphi, sth, cth, X[aurora_sim::kRollRate],
                               X[aurora_sim::kPitchRate], X[aurora_sim::kYawRate], Cr_a);
    Matrix<double, 6, 6> MM = Matrix<double, 6, 6>::Zero(), CC = Matrix<double, 6, 6>::Zero();
    MM.topLeftCorner<3, 3>() = p.m * Matrix<double, 3, 3>::Identity();
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        MM(3 + i, 3 + j) = Mr_a[i][j];
        CC(3 + i, 3 + j) = Cr_a[i][j];
      }
    }
    Matrix<double, 6, 1> GG;
    GG << 0, 0, p.m * p.g, 0, 0, 0;
    Matrix<double, 3, 4> At = Matrix<double, 3, 4>::Zero();
    At.row(2).setOnes();
    Matrix<double, 3, 4> Ar;
    Ar << p.k1, p.k1, -p.k1, -p.k1, -p.k1, p.k1, p.k1, -p.k1, p.k2, -p.k2, p.k2, -p.k2;
    Matrix<double, 6, 4> A;
    A.topRows<3>() = R * At;
    A.bottomRows<3>() = Ar;
    // pinv of a full-column-rank matrix, through the SVD as the reference's pinv.
    const Eigen::JacobiSVD<Matrix<double, 6, 4>> svd(A, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Matrix<double, 4, 6> Sinv = Matrix<double, 4, 6>::Zero();
    for (int i = 0; i < 4; ++i) Sinv(i, i) = 1.0 / svd.singularValues()(i);
    const Matrix<double, 4, 6> As = svd.matrixV() * Sinv * svd.matrixU().transpose();

    // 5. Ma = As MM, Ea = As (CC X(7:12) + GG + [D; 0]).
    const Matrix<double, 4, 6> Ma = As * MM;
    const Matrix<double, 4, 2> Map = Ma.leftCols<2>();
    const Matrix<double, 4, 4> Maa = Ma.rightCols<4>();
    Matrix<double, 6, 1> rates;
    for (int i = 0; i < 6; ++i) rates(i) = X[aurora_sim::kVx + i];
    const Matrix<double, 4, 1> Ea = As * (CC * rates + GG);
    // 6. MP = R' m, GP = R' [0 0 m g].
    const Matrix<double, 3, 3> MP = R.transpose() * p.m;
    const Matrix<double, 3, 1> GP = R.transpose() * Eigen::Vector3d(0, 0, p.m * p.g);
    const Matrix<double, 2, 2> Mpp = MP.topLeftCorner<2, 2>();
    Matrix<double, 2, 4> Mpa = Matrix<double, 2, 4>::Zero();
    Mpa.col(0) = MP.block<2, 1>(0, 2);
    const Matrix<double, 2, 1> Ep = GP.head<2>();
    // 7. Reduced dynamics and the forces and torques.
    const Matrix<double, 2, 2> Mpp_inv = Mpp.inverse();
    const Matrix<double, 4, 4> Dm = Maa - Map * Mpp_inv * Mpa;
    const Matrix<double, 4, 1> Hm = Ea - Map * Mpp_inv * Ep;
    const Matrix<double, 4, 1> eta_a(eta[2], eta[3], eta[4], eta[5]);
    const Matrix<double, 4, 1> Fr = Dm * eta_a + Hm;
    Matrix<double, 6, 1> ftau = A * Fr;
    // 8. Never ask for negative thrust.
    if (ftau(2) < 0) ftau(2) = 0.3 * p.m * p.g;
    Matrix<double, 4, 1> Fd = As * ftau;
    for (int i = 0; i < 4; ++i) {
      if (Fd(i) < 0) Fd(i) = 0;
    }
    // 9. Desired rotor speeds and the voltages that produce them.
    const Matrix<double, 4, 1> Wda = Wd_;
    for (int i = 0; i < 4; ++i) Wd_(i) = std::sqrt(Fd(i) / p.Cf);
    Matrix<double, 4, 1> Vr;
    for (int i = 0; i < 4; ++i) {
      Vr(i) = -p.Vo + p.Jm * p.Rm / p.Km * (Wd_(i) - Wda(i)) / p.Ts +
              (p.Bm * p.Rm / p.Km + p.Kb) * Wd_(i) + p.Ct * p.Rm / (p.Km * p.r) * Wd_(i) * Wd_(i);
    }
    // 10. Inverse of the on-board PD: the references that give these voltages.
    const double sigma = 0.25 * p.Ts;
    const Eigen::Vector4d mix_roll(1, 1, -1, -1), mix_pitch(-1, 1, 1, -1), mix_climb(1, 1, 1, 1),
        mix_yaw(1, -1, 1, -1);
    const double x4 = X[aurora_sim::kRoll], x5 = X[aurora_sim::kPitch];
    const double x9 = X[aurora_sim::kVz], x12 = X[aurora_sim::kYawRate];
    Xr_(0) = x4 + (p.kdp * (Xr_(0) - x4) + sigma * mix_roll.dot(Vr)) / (p.kdp + p.kpp * p.Ts);
    Xr_(1) = x5 + (p.kdt * (Xr_(1) - x5) + sigma * mix_pitch.dot(Vr)) / (p.kdt + p.kpt * p.Ts);
    Xr_(2) = x9 + (p.kdz * (Xr_(2) - x9) + sigma * mix_climb.dot(Vr)) / (p.kdz + p.kpz * p.Ts);
    Xr_(3) = x12 + (p.kds * (Xr_(3) - x12) + sigma * mix_yaw.dot(Vr)) / (p.kds + p.kps * p.Ts);
    // 11. Commands.
    U[0] = std::tanh(Xr_(0) / p.uSat[0]);
    U[1] = std::tanh(-Xr_(1) / p.uSat[1]);
    U[2] = std::tanh(Xr_(2) / p.uSat[2]);
    U[3] = std::tanh(-Xr_(3) / p.uSat[3]);
  }

 private:
  aurora_sim::ArdroneParams<double> p_;
  SvdReferenceGains g_;
  Eigen::Vector4d Wd_;
  Eigen::Vector4d Xr_;  // own references on the on-board channels (roll, pitch, climb, yaw rate)
  double roll_d_ = 0.0, pitch_d_ = 0.0;
};

}  // namespace aurora_control
