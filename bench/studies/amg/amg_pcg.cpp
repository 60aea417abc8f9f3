// Does algebraic multigrid pay for cg's solves? (bench/studies/amg/README.md (section 10.15); issue 15
// names hypre's BoomerAMG as a route to target 1.) Reads the linear system of a dumped
// problem's exact pushing rows (written by amg.py: A in CSR, the right-hand side, the fix's
// warm start, the row scales and tol), and runs preconditioned CG from the warm start to the
// fix's stopping test (max |r_c| / scale_c <= tol) with Jacobi and with one BoomerAMG V-cycle
// per iteration, for a few strength thresholds and smoothers. Prints iterations and the
// measured seconds of the setup, of an iteration, and of the whole solve, one line per run.
// Serial (one MPI process): the question is what an iteration costs against what it saves.
//   amg_pcg SYSTEM_FILE LABEL
#include <HYPRE.h>
#include <HYPRE_IJ_mv.h>
#include <HYPRE_parcsr_ls.h>
#include <mpi.h>

#include <Eigen/SparseCore>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0)
{
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

struct System {
  Eigen::SparseMatrix<double, Eigen::RowMajor> a;
  Eigen::VectorXd rhs, x0, scale;
  double tol = 0.0;
};

// text: n nnz tol / n+1 row pointers / nnz (column value) / n (rhs x0 scale)
System read_system(const std::string &path)
{
  std::ifstream in(path);
  int n = 0;
  long nnz = 0;
  System s;
  in >> n >> nnz >> s.tol;
  std::vector<int> ptr(n + 1);
  for (int &p : ptr) in >> p;
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(nnz);
  for (int r = 0; r < n; ++r)
    for (int k = ptr[r]; k < ptr[r + 1]; ++k) {
      int c = 0;
      double v = 0.0;
      in >> c >> v;
      t.emplace_back(r, c, v);
    }
  s.a.resize(n, n);
  s.a.setFromTriplets(t.begin(), t.end());
  s.rhs.resize(n);
  s.x0.resize(n);
  s.scale.resize(n);
  for (int r = 0; r < n; ++r) in >> s.rhs[r] >> s.x0[r] >> s.scale[r];
  if (!in) throw std::runtime_error("cannot read " + path);
  return s;
}

struct Result {
  int iterations = 0;
  double seconds = 0.0;
};

// PCG on A x = rhs from x0 until max |r| / scale <= tol (the fix's test); z = M^-1 r by precond
Result pcg(const System &s, const std::function<void(const Eigen::VectorXd &, Eigen::VectorXd &)> &precond,
           int maxit = 5000)
{
  const auto t0 = Clock::now();
  Eigen::VectorXd x = s.x0, r = s.rhs - s.a * x, z(x.size()), p, q;
  precond(r, z);
  p = z;
  double rz = r.dot(z);
  int k = 0;
  for (; k < maxit; ++k) {
    if ((r.cwiseAbs().array() / s.scale.array()).maxCoeff() <= s.tol) break;
    q = s.a * p;
    const double alpha = rz / p.dot(q);
    x += alpha * p;
    r -= alpha * q;
    precond(r, z);
    const double rz_new = r.dot(z);
    p = z + (rz_new / rz) * p;
    rz = rz_new;
  }
  return {k, seconds_since(t0)};
}

}    // namespace

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  if (argc != 3) {
    std::fprintf(stderr, "usage: amg_pcg SYSTEM_FILE LABEL\n");
    return 2;
  }
  const System s = read_system(argv[1]);
  const std::string label = argv[2];
  const int n = static_cast<int>(s.rhs.size());
  HYPRE_Init();

  const Eigen::VectorXd inv_d = s.a.diagonal().cwiseInverse();
  const Result jac = pcg(s, [&](const Eigen::VectorXd &r, Eigen::VectorXd &z) {
    z = inv_d.cwiseProduct(r);
  });
  std::printf("%s rows %d nnz/row %.1f | jacobi: %d it, %.4f s (%.1f us/it)\n", label.c_str(), n,
              double(s.a.nonZeros()) / n, jac.iterations, jac.seconds,
              1e6 * jac.seconds / std::max(jac.iterations, 1));

  // the matrix and two vectors in hypre's IJ form (one process owns every row)
  HYPRE_IJMatrix ij;
  HYPRE_IJMatrixCreate(MPI_COMM_WORLD, 0, n - 1, 0, n - 1, &ij);
  HYPRE_IJMatrixSetObjectType(ij, HYPRE_PARCSR);
  HYPRE_IJMatrixInitialize(ij);
  for (int r = 0; r < n; ++r) {
    std::vector<HYPRE_BigInt> cols;
    std::vector<double> vals;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(s.a, r); it; ++it) {
      cols.push_back(it.col());
      vals.push_back(it.value());
    }
    HYPRE_Int nc = static_cast<HYPRE_Int>(cols.size());
    HYPRE_BigInt row = r;
    HYPRE_IJMatrixSetValues(ij, 1, &nc, &row, cols.data(), vals.data());
  }
  HYPRE_IJMatrixAssemble(ij);
  HYPRE_ParCSRMatrix a;
  HYPRE_IJMatrixGetObject(ij, reinterpret_cast<void **>(&a));
  HYPRE_IJVector ib, ix;
  std::vector<HYPRE_BigInt> idx(n);
  for (int r = 0; r < n; ++r) idx[r] = r;
  for (HYPRE_IJVector *v : {&ib, &ix}) {
    HYPRE_IJVectorCreate(MPI_COMM_WORLD, 0, n - 1, v);
    HYPRE_IJVectorSetObjectType(*v, HYPRE_PARCSR);
    HYPRE_IJVectorInitialize(*v);
    std::vector<double> zero(n, 0.0);
    HYPRE_IJVectorSetValues(*v, n, idx.data(), zero.data());
    HYPRE_IJVectorAssemble(*v);
  }
  HYPRE_ParVector b, x;
  HYPRE_IJVectorGetObject(ib, reinterpret_cast<void **>(&b));
  HYPRE_IJVectorGetObject(ix, reinterpret_cast<void **>(&x));

  struct Setting {
    double strong;
    int relax;    // 6: hybrid symmetric Gauss-Seidel, 18: l1-Jacobi
    const char *name;
  };
  for (const Setting &st : {Setting{0.25, 6, "sym GS"}, Setting{0.5, 6, "sym GS"},
                            Setting{0.7, 6, "sym GS"}, Setting{0.5, 18, "l1-Jacobi"}}) {
    HYPRE_Solver amg;
    HYPRE_BoomerAMGCreate(&amg);
    HYPRE_BoomerAMGSetStrongThreshold(amg, st.strong);
    HYPRE_BoomerAMGSetRelaxType(amg, st.relax);
    HYPRE_BoomerAMGSetNumSweeps(amg, 1);
    HYPRE_BoomerAMGSetMaxIter(amg, 1);    // one V-cycle per application
    HYPRE_BoomerAMGSetTol(amg, 0.0);
    HYPRE_BoomerAMGSetPrintLevel(amg, std::getenv("AMG_PRINT") ? 1 : 0);
    const auto t0 = Clock::now();
    HYPRE_BoomerAMGSetup(amg, a, b, x);
    const double setup = seconds_since(t0);
    std::vector<double> buf(n);
    const Result res = pcg(s, [&](const Eigen::VectorXd &r, Eigen::VectorXd &z) {
      HYPRE_IJVectorSetValues(ib, n, idx.data(), r.data());
      std::fill(buf.begin(), buf.end(), 0.0);
      HYPRE_IJVectorSetValues(ix, n, idx.data(), buf.data());
      HYPRE_BoomerAMGSolve(amg, a, b, x);
      HYPRE_IJVectorGetValues(ix, n, idx.data(), buf.data());
      z = Eigen::Map<const Eigen::VectorXd>(buf.data(), n);
    });
    std::printf("%s amg strong %.2f %s: %d it, setup %.4f s, solve %.4f s (%.1f us/it), "
                "setup + solve %.4f s = %.2f x jacobi\n",
                label.c_str(), st.strong, st.name, res.iterations, setup, res.seconds,
                1e6 * res.seconds / std::max(res.iterations, 1), setup + res.seconds,
                (setup + res.seconds) / jac.seconds);
    HYPRE_BoomerAMGDestroy(amg);
  }
  HYPRE_IJMatrixDestroy(ij);
  HYPRE_IJVectorDestroy(ib);
  HYPRE_IJVectorDestroy(ix);
  HYPRE_Finalize();
  MPI_Finalize();
  return 0;
}
