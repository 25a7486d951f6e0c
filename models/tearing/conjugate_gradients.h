#pragma once
// The implicit integrator's conjugate gradients (implicit_integrator.h):
// the multigrid V-cycle as Eigen's ConjugateGradient wants a
// preconditioner, and preconditioned conjugate gradients from x = 0 with
// the products given or carried from the preconditioner's.

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "models/tearing/sheet_multigrid.h"

namespace repose {

// The vectors of conjugate_gradients with carried products, kept from
// solve to solve (no allocation once sized): b the right-hand side, x the
// solution.
struct ConjugateGradientWork {
  Eigen::VectorXd b, x, r, p, z, ap, az;
};

// The multigrid V-cycle as Eigen's ConjugateGradient wants a preconditioner.
class MultigridPreconditioner {
 public:
  MultigridPreconditioner() = default;
  void use(const SheetMultigrid* multigrid, const Eigen::SparseMatrix<double>* system) {
    multigrid_ = multigrid;
    system_ = system;
  }
  template <class Matrix> MultigridPreconditioner& analyzePattern(const Matrix&) { return *this; }
  template <class Matrix> MultigridPreconditioner& factorize(const Matrix&) { return *this; }
  template <class Matrix> MultigridPreconditioner& compute(const Matrix&) { return *this; }
  Eigen::VectorXd solve(const Eigen::VectorXd& r) const { return multigrid_->apply(*system_, r); }
  Eigen::ComputationInfo info() const { return Eigen::Success; }

 private:
  const SheetMultigrid* multigrid_ = nullptr;
  const Eigen::SparseMatrix<double>* system_ = nullptr;
};

// Preconditioned conjugate gradients for A x = b from x = 0 (Eigen's
// ConjugateGradient's recurrences: stops once |r| <= tolerance |b|, r
// updated recursively), with the products A p and the preconditioner
// given; returns x and sets *iterations.
template <class Product, class Precondition>
Eigen::VectorXd conjugate_gradients(const Eigen::VectorXd& b, double tolerance, int max_iterations,
                                    Product&& product, Precondition&& precondition, int* iterations) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
  *iterations = 0;
  const double threshold = tolerance * tolerance * b.squaredNorm();
  if (threshold == 0.0) return x;
  Eigen::VectorXd r = b;
  Eigen::VectorXd p = precondition(r);
  double rz = r.dot(p);
  while (*iterations < max_iterations) {
    const Eigen::VectorXd ap = product(p);
    const double alpha = rz / p.dot(ap);
    x += alpha * p;
    r -= alpha * ap;
    ++*iterations;
    if (r.squaredNorm() < threshold) break;
    const Eigen::VectorXd z = precondition(r);
    const double rz_new = r.dot(z);
    p = z + (rz_new / rz) * p;
    rz = rz_new;
  }
  return x;
}

// The same recurrences with every vector in *work (no allocation once the
// vectors have their size), the products A p not taken but carried: the
// preconditioner gives z and A z (precondition(r, &z, &az)), and A p of
// p = z + beta p_old is A z + beta A p_old. The solution in work->x.
template <class Precondition>
void conjugate_gradients(const Eigen::VectorXd& b, double tolerance, int max_iterations, Precondition&& precondition,
                         ConjugateGradientWork* work, int* iterations) {
  ConjugateGradientWork& w = *work;
  w.x.setZero(b.size());
  *iterations = 0;
  const double threshold = tolerance * tolerance * b.squaredNorm();
  if (threshold == 0.0) return;
  w.r = b;
  precondition(w.r, &w.p, &w.ap);
  double rz = w.r.dot(w.p);
  while (*iterations < max_iterations) {
    const double alpha = rz / w.p.dot(w.ap);
    w.x += alpha * w.p;
    w.r -= alpha * w.ap;
    ++*iterations;
    if (w.r.squaredNorm() < threshold) break;
    precondition(w.r, &w.z, &w.az);
    const double rz_new = w.r.dot(w.z);
    const double beta = rz_new / rz;
    w.p = w.z + beta * w.p;
    w.ap = w.az + beta * w.ap;
    rz = rz_new;
  }
}

}  // namespace repose
