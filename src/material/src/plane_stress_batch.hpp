#pragma once
// Plane-stress J2 returns with linear hardening, many points at once. A chunk's yielding points
// are gathered into a batch; the batch's scalar equations (detail::plane_stress_return's, the
// same residual, start, bracket and stopping rules) are solved in lockstep, one Newton sweep over
// the whole batch at a time, branch-free, so the divisions and square roots that dominate a
// point's return run across SIMD lanes instead of one after the other. A point stops moving once
// its own stopping rule holds, so its result does not depend on which points share its batch
// (the same bits on any thread count or chunking). A point not converged after kSweeps sweeps
// (large increments on rare steps) finishes with the scalar safeguarded solver from its bracket.
// LinearPlaneStressLanes solves; LinearPlaneStressBatch (J2, *MAT_024 and *MAT_004) and
// KinematicPlaneStressBatch (*MAT_003's mixed hardening, metal_plasticity.cpp) write their laws'
// results back. Private to plyform_material.

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "hardening.hpp"

namespace plyform::material::detail {

// The lockstep solve of up to kSize points' scalar equations; the derived batch (Batch) adds
// points with push() and writes their results back in its write_back(). A template, so that each
// batch's solve is its own code, compiled with its law file's floating-point contraction (a
// shared out-of-line copy would round as one of the files only).
template <class Batch>
class LinearPlaneStressLanes {
 public:
  static constexpr std::size_t kSize = 32;
  static constexpr int kSweeps = 4;

  /// Solves the points gathered so far and writes their results back.
  void flush() {
    if (n_ == 0)
      return;
    solve();
    static_cast<Batch*>(this)->write_back();
    n_ = 0;
  }

 protected:
  // Point i's equation: a, b the return's moduli, the yield curve sy0 + hp eps_p, the plastic
  // strain at the start e_n, the trial (p_tr, q_tr, t) and its equivalent stress psi_tr.
  std::size_t push(double a, double b, double sy0, double hp, double e_n, double p_tr, double q_tr,
                   double t, double psi_tr) {
    const std::size_t i = n_++;
    a_[i] = a;
    b_[i] = b;
    sy0_[i] = sy0;
    hp_[i] = hp;
    e_n_[i] = e_n;
    p_tr_[i] = p_tr;
    q_tr_[i] = q_tr;
    t_tr_[i] = t;
    psi_tr_[i] = psi_tr;
    return i;
  }

  /// After a point is pushed: solves the batch once it is full.
  void flush_if_full() {
    if (n_ == kSize)
      flush();
  }

  /// gamma of every point pushed (g_).
  void solve() {
    start();
    bool converged = false;
    for (int sweep = 0; sweep < kSweeps && !converged; ++sweep)
      converged = newton_sweep();
    if (!converged)
      finish_scalar();
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

 protected:
  std::size_t n_ = 0;
  double a_[kSize], b_[kSize], sy0_[kSize], hp_[kSize], e_n_[kSize];
  double p_tr_[kSize], q_tr_[kSize], t_tr_[kSize], psi_tr_[kSize];
  double big_a_[kSize], big_b_[kSize], lo_[kSize], hi_[kSize], g_[kSize], done_[kSize];
};

class LinearPlaneStressBatch : public LinearPlaneStressLanes<LinearPlaneStressBatch> {
 public:
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
    const std::size_t i = push(0.5 * young / (1.0 - nu), 1.5 * young / (1.0 + nu), sy0, hp,
                               eps_p_[point], p_tr, q_tr, t, psi_tr);
    index_[i] = point;
    nu_e_[i] = nu / young;
    flush_if_full();
  }

 private:
  friend class LinearPlaneStressLanes<LinearPlaneStressBatch>;

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
  std::size_t index_[kSize];
  double nu_e_[kSize];
};

// *MAT_003's mixed hardening (metal_plasticity.cpp says why this is the J2 return of the shifted
// stress eta = sigma - alpha with a + H, b + H): the points' gammas solved together, the stress,
// back stress (xx, yy, xy in the history's slots 0, 1, 3), plastic strain and thickness strain
// written back per point by the scalar return's own formulas.
class KinematicPlaneStressBatch : public LinearPlaneStressLanes<KinematicPlaneStressBatch> {
 public:
  /// a, b: the elastic return moduli E / (2 (1 - nu)), 3 G; h_kin: (1 - BETA) E_p; history: the
  /// points' six back-stress slots each.
  KinematicPlaneStressBatch(double a, double b, double nu_e, double h_kin, double* sxx, double* syy,
                            double* sxy, double* eps_p, double* dzz, double* history)
      : a_el_(a),
        b_el_(b),
        nu_e_(nu_e),
        h_kin_(h_kin),
        sxx_(sxx),
        syy_(syy),
        sxy_(sxy),
        eps_p_(eps_p),
        dzz_(dzz),
        history_(history) {}
  KinematicPlaneStressBatch(const KinematicPlaneStressBatch&) = delete;
  KinematicPlaneStressBatch& operator=(const KinematicPlaneStressBatch&) = delete;
  ~KinematicPlaneStressBatch() { flush(); }

  /// A point whose shifted trial (p_tr, q_tr, t of eta) lies outside sigma_y = sy0 + hp eps_p.
  void add(std::size_t point, double sy0, double hp, double p_tr, double q_tr, double t,
           double psi_tr) {
    const std::size_t i =
        push(a_el_ + h_kin_, b_el_ + h_kin_, sy0, hp, eps_p_[point], p_tr, q_tr, t, psi_tr);
    index_[i] = point;
    flush_if_full();
  }

 private:
  friend class LinearPlaneStressLanes<KinematicPlaneStressBatch>;

  // The stress, back stress, plastic strain and thickness strain at gamma, per point.
  void write_back() {
    const double a = a_el_, b = b_el_, h = h_kin_;
    for (std::size_t i = 0; i < n_; ++i) {
      const std::size_t p = index_[i];
      double* ab = history_ + 6 * p;
      const double g = g_[i];
      const double ua = 1.0 / (1.0 + a_[i] * g), ub = 1.0 / (1.0 + b_[i] * g);
      const double pe = p_tr_[i] * ua, qe = q_tr_[i] * ub, te = t_tr_[i] * ub;  // eta at the end
      const double dp = -a * g * pe;  // the stress's change in p
      sxx_[p] += 0.5 * (dp - b * g * qe);
      syy_[p] += 0.5 * (dp + b * g * qe);
      sxy_[p] -= b * g * te;
      ab[0] += 0.5 * h * g * (pe + qe);
      ab[1] += 0.5 * h * g * (pe - qe);
      ab[3] += h * g * te;
      eps_p_[p] += g * std::sqrt(big_a_[i] * ua * ua + big_b_[i] * ub * ub);
      dzz_[p] += -nu_e_ * dp - 0.5 * g * pe;
    }
  }

  double a_el_, b_el_, nu_e_, h_kin_;
  double* sxx_;
  double* syy_;
  double* sxy_;
  double* eps_p_;
  double* dzz_;
  double* history_;
  std::size_t index_[kSize];
};

}  // namespace plyform::material::detail
