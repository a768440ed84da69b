#pragma once
// Plane-stress J2 returns with linear hardening, many points at once. A chunk's yielding points
// are gathered into a batch; the batch's scalar equations (detail::plane_stress_return's, the
// same residual, start, bracket and stopping rules) are solved in lockstep, one Newton sweep over
// the whole batch at a time, branch-free, so the divisions and square roots that dominate a
// point's return run across SIMD lanes instead of one after the other. A point stops moving once
// its own stopping rule holds, so its result does not depend on which points share its batch
// (the same bits on any thread count or chunking). A point not converged after kSweeps sweeps
// (large increments on rare steps) finishes with the scalar safeguarded solver from its bracket.
// Private to plyform_material.

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "hardening.hpp"

namespace plyform::material::detail {

class LinearPlaneStressBatch {
 public:
  static constexpr std::size_t kSize = 32;
  static constexpr int kSweeps = 4;

  /// The point's arrays the results go back to (indexed by the point numbers given to add).
  LinearPlaneStressBatch(double* sxx, double* syy, double* sxy, double* eps_p, double* dzz)
      : sxx_(sxx), syy_(syy), sxy_(sxy), eps_p_(eps_p), dzz_(dzz) {}
  LinearPlaneStressBatch(const LinearPlaneStressBatch&) = delete;
  LinearPlaneStressBatch& operator=(const LinearPlaneStressBatch&) = delete;
  ~LinearPlaneStressBatch() { flush(); }

  /// A point whose trial stress (p_tr = sxx + syy, q_tr = sxx - syy, t) lies outside its yield
  /// surface sigma_y = sy0 + hp eps_p; young and nu its elastic constants. Solves the batch when
  /// it is full.
  void add(std::size_t point, double young, double nu, double sy0, double hp, double p_tr,
           double q_tr, double t, double psi_tr) {
    const std::size_t i = n_++;
    index_[i] = point;
    a_[i] = 0.5 * young / (1.0 - nu);
    b_[i] = 1.5 * young / (1.0 + nu);
    nu_e_[i] = nu / young;
    sy0_[i] = sy0;
    hp_[i] = hp;
    e_n_[i] = eps_p_[point];
    p_tr_[i] = p_tr;
    q_tr_[i] = q_tr;
    t_tr_[i] = t;
    psi_tr_[i] = psi_tr;
    if (n_ == kSize)
      flush();
  }

  /// Solves the points gathered so far and writes their stresses, plastic strain and thickness
  /// strain back.
  void flush() {
    if (n_ == 0)
      return;
    start();
    bool converged = false;
    for (int sweep = 0; sweep < kSweeps && !converged; ++sweep)
      converged = newton_sweep();
    if (!converged)
      finish_scalar();
    write_back();
    n_ = 0;
  }

 private:
  void start() {
    for (std::size_t i = 0; i < n_; ++i) {
      const LinearHardening h{sy0_[i], hp_[i]};
      const double big_a = 0.25 * p_tr_[i] * p_tr_[i];
      const double big_b = 0.75 * q_tr_[i] * q_tr_[i] + 3.0 * t_tr_[i] * t_tr_[i];
      const double sy_n = h.value(e_n_[i]);
      big_a_[i] = big_a;
      big_b_[i] = big_b;
      lo_[i] = 0.0;
      hi_[i] = (psi_tr_[i] / sy_n - 1.0) / std::min(a_[i], b_[i]);
      g_[i] =
          plane_stress_first_step(h, a_[i], b_[i], big_a, big_b, e_n_[i], psi_tr_[i], sy_n, hi_[i]);
      done_[i] = 0.0;
    }
  }

  // One Newton (or bisection) step of every point not yet converged, as solve_decreasing takes
  // it. Returns whether every point has converged.
  bool newton_sweep() {
    double open = 0.0;
#pragma omp simd reduction(+ : open)
    for (std::size_t i = 0; i < n_; ++i) {
      const double g = g_[i], lo_old = lo_[i], hi_old = hi_[i];
      double r = 0.0, dr = 0.0;
      plane_stress_residual(LinearHardening{sy0_[i], hp_[i]}, a_[i], b_[i], big_a_[i], big_b_[i],
                            e_n_[i], g, r, dr);
      const bool above = r > 0.0;
      const double lo = above ? g : lo_old;
      const double hi = above ? hi_old : g;
      const double newton = g - r / dr;
      const bool inside = (newton > lo) & (newton < hi);
      const double gn = inside ? newton : 0.5 * (lo + hi);
      const double step_tol = std::max(plane_stress_step_tol(a_[i], b_[i]), 1e-16 * g);
      // Bitwise, not short-circuit: the loop stays free of branches and vectorises.
      const bool was_done = done_[i] != 0.0;
      const bool at_root = std::abs(r) <= kPlaneStressResidualTol;
      const bool short_step = (hi - lo <= 4e-16 * hi) | (std::abs(gn - g) <= step_tol);
      const bool keep = was_done | at_root;
      const bool now_done = keep | short_step;
      g_[i] = keep ? g : gn;
      lo_[i] = was_done ? lo_old : lo;
      hi_[i] = was_done ? hi_old : hi;
      done_[i] = now_done ? 1.0 : 0.0;
      open += now_done ? 0.0 : 1.0;
    }
    return open == 0.0;
  }

  void finish_scalar() {
    for (std::size_t i = 0; i < n_; ++i) {
      if (done_[i] != 0.0)
        continue;
      const LinearHardening h{sy0_[i], hp_[i]};
      const double a = a_[i], b = b_[i], big_a = big_a_[i], big_b = big_b_[i], e_n = e_n_[i];
      g_[i] = solve_decreasing(
          [&](double g, double& r, double& dr) {
            plane_stress_residual(h, a, b, big_a, big_b, e_n, g, r, dr);
          },
          lo_[i], hi_[i], kPlaneStressResidualTol, plane_stress_step_tol(a, b), g_[i]);
    }
  }

  // The backward-Euler stress at gamma (shell.cpp's plane_stress_return_kernel says why),
  // computed across the batch, then scattered to the points.
  void write_back() {
    double sxx[kSize], syy[kSize], sxy[kSize], eps_p[kSize], d_dzz[kSize];
    for (std::size_t i = 0; i < n_; ++i) {
      const double g = g_[i];
      const double ua = 1.0 / (1.0 + a_[i] * g), ub = 1.0 / (1.0 + b_[i] * g);
      const double pp = p_tr_[i] * ua, qq = q_tr_[i] * ub;
      sxx[i] = 0.5 * (pp + qq);
      syy[i] = 0.5 * (pp - qq);
      sxy[i] = t_tr_[i] * ub;
      eps_p[i] = e_n_[i] + g * std::sqrt(big_a_[i] * ua * ua + big_b_[i] * ub * ub);
      d_dzz[i] = -nu_e_[i] * (pp - p_tr_[i]) - 0.5 * g * pp;
    }
    for (std::size_t i = 0; i < n_; ++i) {
      const std::size_t p = index_[i];
      sxx_[p] = sxx[i];
      syy_[p] = syy[i];
      sxy_[p] = sxy[i];
      eps_p_[p] = eps_p[i];
      dzz_[p] += d_dzz[i];
    }
  }

  double* sxx_;
  double* syy_;
  double* sxy_;
  double* eps_p_;
  double* dzz_;
  std::size_t n_ = 0;
  std::size_t index_[kSize];
  double a_[kSize], b_[kSize], nu_e_[kSize], sy0_[kSize], hp_[kSize], e_n_[kSize];
  double p_tr_[kSize], q_tr_[kSize], t_tr_[kSize], psi_tr_[kSize];
  double big_a_[kSize], big_b_[kSize], lo_[kSize], hi_[kSize], g_[kSize], done_[kSize];
};

}  // namespace plyform::material::detail
