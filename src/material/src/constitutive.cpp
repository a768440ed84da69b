#include "plyform/material/constitutive.hpp"

#include "plyform/material/law_registry.hpp"

#include <cmath>

namespace plyform::material {

// ---------------------------------------------------------------------------------------------
// *MAT_ELASTIC, Jaumann rate.
//
// sigma_dot = C : D + W sigma - sigma W. For a pure spin the exact solution is a rotation,
// sigma(t) = R sigma0 R^T with R_dot = W R. Over one step we use the Cayley (Hughes-Winget)
// rotation Q = (I - B)^-1 (I + B), B = dt W / 2, which is orthogonal for any dt and equals
// I + dt W + O(dt^2); with b the axial vector of B (|b|^2 = u^2 + v^2 + s^2 below),
// Q = I + 2 / (1 + |b|^2) (B + B^2). Then sigma_new = Q sigma Q^T + dt C : D, i.e.
// sigma_new = sigma + dt (C : D + W sigma - sigma W) + O(dt^2).
//
// B = [[0, u, -s], [-u, 0, v], [s, -v, 0]] with u = dt/2 W_12, v = dt/2 W_23, s = dt/2 W_31;
// B^2 = [[-u^2 - s^2, s v, u v], [s v, -u^2 - v^2, u s], [u v, u s, -s^2 - v^2]].
// ---------------------------------------------------------------------------------------------
namespace {

// The point loop, with restrict-qualified parameters (GCC honours restrict on parameters, not on
// local copies) so that it vectorises without run-time alias checks.
void elastic_jaumann_kernel(std::size_t n, double lam_dt, double two_mu_dt, double half_dt,
                            const double* __restrict dxx, const double* __restrict dyy,
                            const double* __restrict dzz, const double* __restrict dxy,
                            const double* __restrict dyz, const double* __restrict dzx,
                            const double* __restrict wxy, const double* __restrict wyz,
                            const double* __restrict wzx, double* __restrict sxx,
                            double* __restrict syy, double* __restrict szz, double* __restrict sxy,
                            double* __restrict syz, double* __restrict szx) {
  for (std::size_t p = 0; p < n; ++p) {
    // Incremental rotation Q (rows q1., q2., q3.).
    const double u = half_dt * wxy[p];
    const double v = half_dt * wyz[p];
    const double s = half_dt * wzx[p];
    const double k = 2.0 / (1.0 + u * u + v * v + s * s);
    const double q11 = 1.0 - k * (u * u + s * s);
    const double q22 = 1.0 - k * (u * u + v * v);
    const double q33 = 1.0 - k * (s * s + v * v);
    const double q12 = k * (u + s * v);
    const double q21 = k * (-u + s * v);
    const double q23 = k * (v + u * s);
    const double q32 = k * (-v + u * s);
    const double q31 = k * (s + u * v);
    const double q13 = k * (-s + u * v);

    const double a11 = sxx[p], a22 = syy[p], a33 = szz[p];
    const double a12 = sxy[p], a23 = syz[p], a31 = szx[p];

    // T = Q sigma.
    const double t11 = q11 * a11 + q12 * a12 + q13 * a31;
    const double t12 = q11 * a12 + q12 * a22 + q13 * a23;
    const double t13 = q11 * a31 + q12 * a23 + q13 * a33;
    const double t21 = q21 * a11 + q22 * a12 + q23 * a31;
    const double t22 = q21 * a12 + q22 * a22 + q23 * a23;
    const double t23 = q21 * a31 + q22 * a23 + q23 * a33;
    const double t31 = q31 * a11 + q32 * a12 + q33 * a31;
    const double t32 = q31 * a12 + q32 * a22 + q33 * a23;
    const double t33 = q31 * a31 + q32 * a23 + q33 * a33;

    // C : D dt.
    const double vol = lam_dt * (dxx[p] + dyy[p] + dzz[p]);

    // sigma = T Q^T + dt C : D.
    sxx[p] = t11 * q11 + t12 * q12 + t13 * q13 + vol + two_mu_dt * dxx[p];
    syy[p] = t21 * q21 + t22 * q22 + t23 * q23 + vol + two_mu_dt * dyy[p];
    szz[p] = t31 * q31 + t32 * q32 + t33 * q33 + vol + two_mu_dt * dzz[p];
    sxy[p] = t11 * q21 + t12 * q22 + t13 * q23 + two_mu_dt * dxy[p];
    syz[p] = t21 * q31 + t22 * q32 + t23 * q33 + two_mu_dt * dyz[p];
    szx[p] = t31 * q11 + t32 * q12 + t33 * q13 + two_mu_dt * dzx[p];
  }
}

}  // namespace

void elastic_jaumann(const core::ElasticMaterial& m, std::size_t n, ConstSymView d,
                     const double* w_xy, const double* w_yz, const double* w_zx, double dt,
                     SymView sigma) {
  const double mu = m.young / (2.0 * (1.0 + m.poisson));
  const double lambda = m.young * m.poisson / ((1.0 + m.poisson) * (1.0 - 2.0 * m.poisson));
  elastic_jaumann_kernel(n, lambda * dt, 2.0 * mu * dt, 0.5 * dt, d.xx, d.yy, d.zz, d.xy, d.yz,
                         d.zx, w_xy, w_yz, w_zx, sigma.xx, sigma.yy, sigma.zz, sigma.xy, sigma.yz,
                         sigma.zx);
}

// ---------------------------------------------------------------------------------------------
// *MAT_MOONEY-RIVLIN_RUBBER (027).
//
// W(I1, I2, III) = A (I1 - 3) + B (I2 - 3) + C (III^-2 - 1) + D (III - 1)^2 with the invariants
// of the right Cauchy-Green tensor Cr = F^T F: I1 = tr Cr, I2 = (I1^2 - tr Cr^2) / 2,
// III = det Cr = J^2.
//
// Derivatives: dI1/dCr = I, dI2/dCr = I1 I - Cr, dIII/dCr = III Cr^-1, so
//   S = 2 dW/dCr = 2 [W1 I + W2 (I1 I - Cr) + W3 III Cr^-1],
//   W1 = A, W2 = B, W3 = dW/dIII = -2 C III^-3 + 2 D (III - 1).
// Push forward, sigma = (1/J) F S F^T, with F F^T = b, F Cr F^T = b^2, F Cr^-1 F^T = I:
//   sigma = (2/J) [A b + B (I1 b - b^2)] + 2 J W3 I
//         = (2/J) [(A + B I1) b - B b^2] + [4 D J (J^2 - 1) - 4 C J^-5] I.
// Checks: at F = I, sigma = (2 A + 4 B - 4 C) I = 0 because C = A/2 + B. Linearised at F = I
// (b = I + 2 eps, J = 1 + tr eps): deviatoric part 4 (A + B) dev(eps), so G = 2 (A + B); mean
// stress (28 A / 3 + 64 B / 3 + 8 D) tr eps, and with LS-DYNA's D(nu) this is
// K = 2 G (1 + nu) / (3 (1 - 2 nu)), the bulk modulus of the same G and nu.
// ---------------------------------------------------------------------------------------------
namespace {

void mooney_rivlin_kernel(std::size_t n, double a, double b, double four_c, double four_d,
                          const double* __restrict f11, const double* __restrict f12,
                          const double* __restrict f13, const double* __restrict f21,
                          const double* __restrict f22, const double* __restrict f23,
                          const double* __restrict f31, const double* __restrict f32,
                          const double* __restrict f33, double* __restrict sxx,
                          double* __restrict syy, double* __restrict szz, double* __restrict sxy,
                          double* __restrict syz, double* __restrict szx) {
  for (std::size_t p = 0; p < n; ++p) {
    const double x11 = f11[p], x12 = f12[p], x13 = f13[p];
    const double x21 = f21[p], x22 = f22[p], x23 = f23[p];
    const double x31 = f31[p], x32 = f32[p], x33 = f33[p];

    // Left Cauchy-Green tensor b = F F^T (rows of F dotted).
    const double bxx = x11 * x11 + x12 * x12 + x13 * x13;
    const double byy = x21 * x21 + x22 * x22 + x23 * x23;
    const double bzz = x31 * x31 + x32 * x32 + x33 * x33;
    const double bxy = x11 * x21 + x12 * x22 + x13 * x23;
    const double byz = x21 * x31 + x22 * x32 + x23 * x33;
    const double bzx = x31 * x11 + x32 * x12 + x33 * x13;

    // b^2 (symmetric).
    const double b2xx = bxx * bxx + bxy * bxy + bzx * bzx;
    const double b2yy = bxy * bxy + byy * byy + byz * byz;
    const double b2zz = bzx * bzx + byz * byz + bzz * bzz;
    const double b2xy = bxx * bxy + bxy * byy + bzx * byz;
    const double b2yz = bxy * bzx + byy * byz + byz * bzz;
    const double b2zx = bzx * bxx + byz * bxy + bzz * bzx;

    const double jac = x11 * (x22 * x33 - x23 * x32) - x12 * (x21 * x33 - x23 * x31) +
                       x13 * (x21 * x32 - x22 * x31);
    const double inv_j = 1.0 / jac;
    const double inv_j2 = inv_j * inv_j;
    const double inv_j5 = inv_j2 * inv_j2 * inv_j;
    const double i1 = bxx + byy + bzz;

    const double c1 = 2.0 * inv_j * (a + b * i1);  // factor of b
    const double c2 = -2.0 * inv_j * b;            // factor of b^2
    const double pr = four_d * jac * (jac * jac - 1.0) - four_c * inv_j5;

    sxx[p] = c1 * bxx + c2 * b2xx + pr;
    syy[p] = c1 * byy + c2 * b2yy + pr;
    szz[p] = c1 * bzz + c2 * b2zz + pr;
    sxy[p] = c1 * bxy + c2 * b2xy;
    syz[p] = c1 * byz + c2 * b2yz;
    szx[p] = c1 * bzx + c2 * b2zx;
  }
}

}  // namespace

void mooney_rivlin_cauchy(const core::MooneyRivlinMaterial& m, std::size_t n,
                          const double* const f[9], SymView sigma) {
  const double nu = m.poisson;
  const double c = 0.5 * m.a + m.b;
  const double d = (m.a * (5.0 * nu - 2.0) + m.b * (11.0 * nu - 5.0)) / (2.0 * (1.0 - 2.0 * nu));
  mooney_rivlin_kernel(n, m.a, m.b, 4.0 * c, 4.0 * d, f[0], f[1], f[2], f[3], f[4], f[5], f[6],
                       f[7], f[8], sigma.xx, sigma.yy, sigma.zz, sigma.xy, sigma.yz, sigma.zx);
}

double dilatational_wave_speed(const core::Material& m) {
  const double k = bulk_modulus(m);
  const double g = shear_modulus(m);
  return std::sqrt((k + 4.0 / 3.0 * g) / density(m));
}

}  // namespace plyform::material
