// The triangle's Jacobian J = dQ/dX (docs/formation.md, eq. T4) in closed
// form and the pseudo-inverses its laws use, without an SVD: J has rank 8,
// its null vector (the roll about the median, n_i = m x (p_i - c)) is known,
// so J+ = (J^T J + n n^T)^-1 J^T with |n| = 1, and likewise for the
// orientation rows JO = D [2I, -I, -I] (D m = 0; [2I, -I, -I] has
// orthogonal rows of norm sqrt 6: JO+ = [2I, -I, -I]^T D+ / 6), each solved
// as least squares by QR (leastSquaresQr). The shape rows JS have full
// rank: JS+ = JS^T (JS JS^T)^-1. Fixed loops only (host, device, SIMD lanes).
#pragma once

#include <cmath>

#include "aurora_common/host_device.h"
#include "aurora_common/scalar_math.h"

namespace aurora_control {
namespace triangle_detail {

template <typename T>
AURORA_HD inline T distance(const T a[3], const T b[3]) {
  using std::sqrt;
  const T d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

// m = 2 p1 - p2 - p3: three times robot 1's offset from the centroid.
template <typename T>
AURORA_HD inline void median(const T X[9], T m[3]) {
  for (int i = 0; i < 3; ++i) m[i] = T(2) * X[i] - X[3 + i] - X[6 + i];
}

// The rows of D (eq. T4) are w_i times a row of [m]x: w_i = 1 / (the sum
// of the squares of m's other two components), 0 where that is 0 (a
// singular angle: its row is zeroed).
template <typename T>
AURORA_HD inline void orientationWeights(const T m[3], T w[3]) {
  using aurora_common::select;
  const T den[3] = {m[1] * m[1] + m[2] * m[2], m[0] * m[0] + m[2] * m[2], m[0] * m[0] + m[1] * m[1]};
  for (int i = 0; i < 3; ++i) w[i] = select(den[i] == T(0), T(0), T(1) / den[i]);
}

template <typename T>
AURORA_HD inline void cross(const T a[3], const T b[3], T c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

// Solves A x = b for a symmetric positive definite A (Cholesky, in place:
// A's lower triangle, all it reads, becomes its factor; b the solution).
template <typename T, int N>
AURORA_HD inline void solveSpd(T A[N][N], T b[N]) {
  using std::sqrt;
  for (int j = 0; j < N; ++j) {
    for (int k = 0; k < j; ++k) A[j][j] = A[j][j] - A[j][k] * A[j][k];
    A[j][j] = sqrt(A[j][j]);
    for (int i = j + 1; i < N; ++i) {
      for (int k = 0; k < j; ++k) A[i][j] = A[i][j] - A[i][k] * A[j][k];
      A[i][j] = A[i][j] / A[j][j];
    }
  }
  for (int i = 0; i < N; ++i) {  // L y = b
    for (int k = 0; k < i; ++k) b[i] = b[i] - A[i][k] * b[k];
    b[i] = b[i] / A[i][i];
  }
  for (int i = N - 1; i >= 0; --i) {  // L^T x = y
    for (int k = i + 1; k < N; ++k) b[i] = b[i] - A[k][i] * b[k];
    b[i] = b[i] / A[i][i];
  }
}

// The least-squares solution x of A x = b (A: M x N, full column rank) by
// Householder QR, without forming A^T A: its error grows with cond(A), not
// cond(A)^2. The pseudo-inverses with a known null direction (J's roll, D's
// median) are such problems with that direction appended as a row
// (min |J x - v|^2 + (n^T x)^2 has x orthogonal to n). In single precision
// the normal equations' Cholesky lost positive definiteness where the
// orientation rows' weights grow (psi near +-pi/2: a pivot of -3e-5, sqrt
// of it NaN; about 1 % of the float triangle delay study diverged where
// double flew). Branch-free (SIMD lanes: the reflector's sign by select).
template <typename T, int M, int N>
AURORA_HD inline void leastSquaresQr(T A[M][N], T b[M], T x[N]) {
  using aurora_common::select;
  using std::sqrt;
  for (int j = 0; j < N; ++j) {
    T below = T(0);
    for (int i = j + 1; i < M; ++i) below = below + A[i][j] * A[i][j];
    const T norm = sqrt(A[j][j] * A[j][j] + below);
    const T alpha = select(A[j][j] < T(0), norm, -norm);  // the sign away from A[j][j]: no cancellation
    const T v0 = A[j][j] - alpha;
    const T vv = v0 * v0 + below;
    const T tau = select(vv == T(0), T(0), T(2) / vv);
    for (int k = j + 1; k < N; ++k) {
      T s = v0 * A[j][k];
      for (int i = j + 1; i < M; ++i) s = s + A[i][j] * A[i][k];
      s = s * tau;
      A[j][k] = A[j][k] - s * v0;
      for (int i = j + 1; i < M; ++i) A[i][k] = A[i][k] - s * A[i][j];
    }
    T s = v0 * b[j];
    for (int i = j + 1; i < M; ++i) s = s + A[i][j] * b[i];
    s = s * tau;
    b[j] = b[j] - s * v0;
    for (int i = j + 1; i < M; ++i) b[i] = b[i] - s * A[i][j];
    A[j][j] = alpha;
  }
  for (int i = N - 1; i >= 0; --i) {  // R x = Q^T b
    T r = b[i];
    for (int k = i + 1; k < N; ++k) r = r - A[i][k] * x[k];
    x[i] = r / A[i][i];
  }
}

template <typename T>
class TriangleJacobian {
 public:
  AURORA_HD explicit TriangleJacobian(const T X[9]) {
    using std::sqrt;
    for (int i = 0; i < 9; ++i) X_[i] = X[i];
    const T p = distance(X, X + 3), q = distance(X, X + 6);
    T u12[3], u13[3], c[3];
    for (int i = 0; i < 3; ++i) u12[i] = (X[i] - X[3 + i]) / p, u13[i] = (X[i] - X[6 + i]) / q;
    // beta's cosine and sine from the unit sides (not cos and sin of the
    // acos of the cosine law: in float its argument rounds past 1 on a
    // narrow angle, sin then 0 and the shape rows infinite).
    cross(u12, u13, c);
    const T cb = u12[0] * u13[0] + u12[1] * u13[1] + u12[2] * u13[2];
    const T sb = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    for (int i = 0; i < 3; ++i) {
      S_[0][i] = u12[i], S_[0][3 + i] = -u12[i], S_[0][6 + i] = T(0);
      S_[1][i] = u13[i], S_[1][3 + i] = T(0), S_[1][6 + i] = -u13[i];
      const T dc2 = (cb * u12[i] - u13[i]) / p, dc3 = (cb * u13[i] - u12[i]) / q;
      S_[2][i] = (dc2 + dc3) / sb;  // -(dc1) / sb, dc1 = -(dc2 + dc3)
      S_[2][3 + i] = -dc2 / sb;
      S_[2][6 + i] = -dc3 / sb;
    }
    median(X, m_);
    T w[3];
    orientationWeights(m_, w);
    const T rows[3][3] = {{T(0), -m_[2], m_[1]}, {m_[2], T(0), -m_[0]}, {-m_[1], m_[0], T(0)}};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) D_[i][j] = w[i] * rows[i][j];
    }
  }

  // JS+ y (3 -> 9).
  AURORA_HD void shapePinv(const T y[3], T out[9]) const {
    T G[3][3], z[3] = {y[0], y[1], y[2]};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) G[i][j] = dot9(S_[i], S_[j]);
    }
    solveSpd<T, 3>(G, z);
    for (int k = 0; k < 9; ++k) out[k] = S_[0][k] * z[0] + S_[1][k] * z[1] + S_[2][k] * z[2];
  }

  // JO+ y (3 -> 9): [2I, -I, -I]^T D+ y / 6.
  AURORA_HD void orientationPinv(const T y[3], T out[9]) const {
    T z[3];
    dPinv(y, z);
    for (int i = 0; i < 3; ++i) {
      out[i] = T(2) * z[i] / T(6);
      out[3 + i] = -z[i] / T(6);
      out[6 + i] = -z[i] / T(6);
    }
  }

  // b minus its part in the shape rows' row space: N_S b = b - JS+ JS b.
  AURORA_HD void removeShape(T b[9]) const {
    const T y[3] = {dot9(S_[0], b), dot9(S_[1], b), dot9(S_[2], b)};
    T back[9];
    shapePinv(y, back);
    for (int k = 0; k < 9; ++k) b[k] = b[k] - back[k];
  }

  // N_O b = b - JO+ JO b.
  AURORA_HD void removeOrientation(T b[9]) const {
    T y[3];
    orientationRows(b, y);
    T back[9];
    orientationPinv(y, back);
    for (int k = 0; k < 9; ++k) b[k] = b[k] - back[k];
  }

  // J+ v (9 -> 9) for J = [JP; JS; JO]: the least-squares solution of
  // [J; n^T] x = [v; 0], i.e. (J^T J + n n^T)^-1 J^T v (leastSquaresQr).
  AURORA_HD void jointPinv(const T v[9], T out[9]) const {
    T rows[10][9], b[10];
    fullRows(rows);
    rollDirection(rows[9]);
    for (int i = 0; i < 9; ++i) b[i] = v[i];
    b[9] = T(0);
    leastSquaresQr<T, 10, 9>(rows, b, out);
  }

 private:
  AURORA_HD static T dot9(const T a[9], const T b[9]) {
    T s = a[0] * b[0];
    for (int k = 1; k < 9; ++k) s = s + a[k] * b[k];
    return s;
  }

  // JO b = D (2 b1 - b2 - b3).
  AURORA_HD void orientationRows(const T b[9], T y[3]) const {
    const T Bb[3] = {T(2) * b[0] - b[3] - b[6], T(2) * b[1] - b[4] - b[7], T(2) * b[2] - b[5] - b[8]};
    for (int i = 0; i < 3; ++i) y[i] = D_[i][0] * Bb[0] + D_[i][1] * Bb[1] + D_[i][2] * Bb[2];
  }

  // D+ y = (D^T D + mh mh^T)^-1 D^T y, mh = m / |m| (D's null direction):
  // the least-squares solution of [D; mh^T] z = [y; 0] (leastSquaresQr).
  AURORA_HD void dPinv(const T y[3], T z[3]) const {
    using std::sqrt;
    const T norm = sqrt(m_[0] * m_[0] + m_[1] * m_[1] + m_[2] * m_[2]);
    T A[4][3], b[4] = {y[0], y[1], y[2], T(0)};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) A[i][j] = D_[i][j];
      A[3][i] = m_[i] / norm;
    }
    leastSquaresQr<T, 4, 3>(A, b, z);
  }

  // J's nine rows: JP = (1/3)[I I I], JS, JO = D [2I, -I, -I].
  AURORA_HD void fullRows(T (*rows)[9]) const {
    for (int r = 0; r < 3; ++r) {
      for (int k = 0; k < 9; ++k) {
        rows[r][k] = k % 3 == r ? T(1) / T(3) : T(0);
        rows[3 + r][k] = S_[r][k];
        const T d = D_[r][k % 3];
        rows[6 + r][k] = k < 3 ? T(2) * d : -d;
      }
    }
  }

  // J's null direction: n_i = m x (p_i - c), normalised.
  AURORA_HD void rollDirection(T* n) const {
    using std::sqrt;
    T c[3];
    for (int i = 0; i < 3; ++i) c[i] = (X_[i] + X_[3 + i] + X_[6 + i]) / T(3);
    T s = T(0);
    for (int r = 0; r < 3; ++r) {
      const T d[3] = {X_[3 * r] - c[0], X_[3 * r + 1] - c[1], X_[3 * r + 2] - c[2]};
      cross(m_, d, n + 3 * r);
      for (int i = 0; i < 3; ++i) s = s + n[3 * r + i] * n[3 * r + i];
    }
    const T norm = sqrt(s);
    for (int k = 0; k < 9; ++k) n[k] = n[k] / norm;
  }

  T X_[9];
  T S_[3][9];  // JS: the rows of p, q, beta
  T D_[3][3];
  T m_[3];
};

}  // namespace triangle_detail
}  // namespace aurora_control
