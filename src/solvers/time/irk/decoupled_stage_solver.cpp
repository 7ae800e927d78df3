#include "catena/solvers/time/irk/decoupled_stage_solver.hpp"

#include <cmath>
#include <sstream>
#include <vector>

#include "catena/solvers/newton/direct_newton.hpp"
#include "catena/solvers/newton/mumps_status.hpp"
#include "catena/solvers/time/irk/block_matrix.hpp"
#include "catena/solvers/time/irk/interleaved_vectors.hpp"

namespace catena::solvers {
namespace {

// One diagonal block of the transformed system: an n × n matrix (real eigenvalue) or a
// 2n × 2n one (complex pair), its MUMPS KSP and its block vectors.
struct Block {
  EigenBlock where;
  MatHandle single;                   // size 1: M′ + hλ C + h²λ² K, K's pattern
  std::unique_ptr<BlockMatrix> pair;  // size 2: [R −S; S R], interleaved
  KspHandle ksp;
  VecHandle rhs, solution, row_scale;

  Mat matrix() const { return pair ? pair->matrix() : single.get(); }
};

}  // namespace

struct DecoupledStageSolver::Impl {
  int s = 0;
  Eigen::MatrixXd A, A2;
  TableauDecomposition form;
  std::vector<double> T, T_inv;  // row-major copies for the per-DOF transforms
  PetscInt n_owned = 0;
  std::vector<Block> blocks;
  MatHandle shell;
  StageMatrixParts parts;
  std::vector<VecHandle> x_parts, y_parts, Cx, Kx;  // the shell product's work vectors
  CallbackGuard own_guard;
  CallbackGuard* guard = &own_guard;
  std::string failure;
  bool factored = false;  // the blocks' factorisations match the last assemble()

  void transform_in(Vec r) {
    const PetscScalar* x = nullptr;
    CATENA_PETSC(VecGetArrayRead(r, &x));
    std::vector<PetscScalar*> z(blocks.size());
    for (size_t b = 0; b < blocks.size(); ++b)
      CATENA_PETSC(VecGetArrayWrite(blocks[b].rhs.get(), &z[b]));
    for (PetscInt l = 0; l < n_owned; ++l) {
      const PetscScalar* xl = x + l * s;
      for (size_t b = 0; b < blocks.size(); ++b) {
        const int o = blocks[b].where.offset, m = blocks[b].where.size;
        for (int k = 0; k < m; ++k) {
          const double* row = &T_inv[static_cast<size_t>((o + k) * s)];
          double sum = 0.0;
          for (int i = 0; i < s; ++i) sum += row[i] * xl[i];
          z[b][l * m + k] = sum;
        }
      }
    }
    for (size_t b = 0; b < blocks.size(); ++b)
      CATENA_PETSC(VecRestoreArrayWrite(blocks[b].rhs.get(), &z[b]));
    CATENA_PETSC(VecRestoreArrayRead(r, &x));
  }

  void transform_out(Vec y) {
    PetscScalar* out = nullptr;
    CATENA_PETSC(VecGetArrayWrite(y, &out));
    std::vector<const PetscScalar*> w(blocks.size());
    for (size_t b = 0; b < blocks.size(); ++b)
      CATENA_PETSC(VecGetArrayRead(blocks[b].solution.get(), &w[b]));
    std::vector<double> wl(static_cast<size_t>(s));
    for (PetscInt l = 0; l < n_owned; ++l) {
      for (size_t b = 0; b < blocks.size(); ++b) {
        const int o = blocks[b].where.offset, m = blocks[b].where.size;
        for (int k = 0; k < m; ++k) wl[static_cast<size_t>(o + k)] = w[b][l * m + k];
      }
      for (int i = 0; i < s; ++i) {
        const double* row = &T[static_cast<size_t>(i * s)];
        double sum = 0.0;
        for (int j = 0; j < s; ++j) sum += row[j] * wl[static_cast<size_t>(j)];
        out[l * s + i] = sum;
      }
    }
    for (size_t b = 0; b < blocks.size(); ++b)
      CATENA_PETSC(VecRestoreArrayRead(blocks[b].solution.get(), &w[b]));
    CATENA_PETSC(VecRestoreArrayWrite(y, &out));
  }

  // The block's MUMPS status after a factorisation or solve: empty if fine.
  static std::string block_failure(size_t b, const Block& block, const char* when) {
    const DirectSolveStatus status = direct_solve_status(block.ksp.get());
    if (!status.failed()) return {};
    std::ostringstream os;
    os << "decoupled stage block " << b << " (" << (block.where.size == 1 ? "real" : "complex")
       << " eigenvalue) failed in its " << when << " (" << status.describe() << ")";
    return os.str();
  }

  void factor() {
    failure.clear();
    factored = true;
    for (size_t b = 0; b < blocks.size() && failure.empty(); ++b) {
      Block& block = blocks[b];
      CATENA_PETSC(KSPSetOperators(block.ksp.get(), block.matrix(), block.matrix()));
      CATENA_PETSC(KSPSetUp(block.ksp.get()));
      while (enlarge_mumps_workspace(block.ksp.get(), direct_solve_status(block.ksp.get())))
        CATENA_PETSC(KSPSetUp(block.ksp.get()));
      failure = block_failure(b, block, "factorisation");
    }
  }

  bool solve(Vec r, Vec y) {
    if (!factored) factor();
    if (!failure.empty()) return false;  // a failed factorisation: nothing to solve with
    transform_in(r);
    for (size_t b = 0; b < blocks.size(); ++b) {
      Block& block = blocks[b];
      CATENA_PETSC(KSPSolve(block.ksp.get(), block.rhs.get(), block.solution.get()));
      failure = block_failure(b, block, "solve");
      if (!failure.empty()) return false;
    }
    transform_out(y);
    return true;
  }

  // y = P (I ⊗ M′ + h A ⊗ C + h² A² ⊗ K) x, with the tableau's own A and A².
  void multiply(Vec x, Vec y) {
    if (!parts.K) throw std::logic_error("DecoupledStageSolver: multiply before assemble");
    std::vector<Vec> xs, ys, cx, kx;
    for (int i = 0; i < s; ++i) {
      xs.push_back(x_parts[static_cast<size_t>(i)].get());
      ys.push_back(y_parts[static_cast<size_t>(i)].get());
      cx.push_back(Cx[static_cast<size_t>(i)].get());
      kx.push_back(Kx[static_cast<size_t>(i)].get());
    }
    split_interleaved(x, xs);
    for (int j = 0; j < s; ++j) {
      CATENA_PETSC(MatMult(parts.C, xs[static_cast<size_t>(j)], cx[static_cast<size_t>(j)]));
      CATENA_PETSC(MatMult(parts.K, xs[static_cast<size_t>(j)], kx[static_cast<size_t>(j)]));
    }
    std::vector<double> wc(static_cast<size_t>(s)), wk(static_cast<size_t>(s));
    for (int i = 0; i < s; ++i) {
      Vec yi = ys[static_cast<size_t>(i)];
      CATENA_PETSC(MatMult(parts.M, xs[static_cast<size_t>(i)], yi));
      for (int j = 0; j < s; ++j) {
        wc[static_cast<size_t>(j)] = parts.h * A(i, j);
        wk[static_cast<size_t>(j)] = parts.h * parts.h * A2(i, j);
      }
      CATENA_PETSC(VecMAXPY(yi, s, wc.data(), cx.data()));
      CATENA_PETSC(VecMAXPY(yi, s, wk.data(), kx.data()));
      if (parts.row_scale) CATENA_PETSC(VecPointwiseMult(yi, yi, parts.row_scale));
    }
    join_interleaved(ys, y);
  }

  static PetscErrorCode shell_mult(Mat J, Vec x, Vec y) {
    void* ctx = nullptr;
    if (MatShellGetContext(J, &ctx) != 0) return PETSC_ERR_LIB;
    auto* self = static_cast<Impl*>(ctx);
    return self->guard->run([&] { self->multiply(x, y); });
  }

  static PetscErrorCode pc_setup(PC pc) {
    void* ctx = nullptr;
    if (PCShellGetContext(pc, &ctx) != 0) return PETSC_ERR_LIB;
    auto* self = static_cast<Impl*>(ctx);
    return self->guard->run([&] {
      CATENA_PETSC(PCSetFailedReason(pc, PC_NOERROR));
      // Already factored for this assembly if real_block() asked first.
      if (!self->factored) self->factor();
    });
  }

  static PetscErrorCode pc_apply(PC pc, Vec r, Vec y) {
    void* ctx = nullptr;
    if (PCShellGetContext(pc, &ctx) != 0) return PETSC_ERR_LIB;
    auto* self = static_cast<Impl*>(ctx);
    return self->guard->run([&] {
      if (self->solve(r, y)) {
        CATENA_PETSC(PCSetFailedReason(pc, PC_NOERROR));
      } else {
        // SNES sees a failed linear solve (KSP_DIVERGED_PC_FAILED) and an infinite update.
        CATENA_PETSC(PCSetFailedReason(pc, PC_SUBPC_ERROR));
        CATENA_PETSC(VecSetInf(y));
      }
    });
  }
};

DecoupledStageSolver::DecoupledStageSolver(Mat pattern, const Eigen::MatrixXd& A,
                                           const Eigen::MatrixXd& A2,
                                           const TableauDecomposition& form,
                                           const std::string& prefix, Pivoting pivoting)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.s = static_cast<int>(A.rows());
  m.A = A;
  m.A2 = A2;
  m.form = form;
  for (int i = 0; i < m.s; ++i)
    for (int j = 0; j < m.s; ++j) {
      m.T.push_back(form.T(i, j));
      m.T_inv.push_back(form.T_inv(i, j));
    }
  MPI_Comm comm = PETSC_COMM_SELF;
  CATENA_PETSC(PetscObjectGetComm(reinterpret_cast<PetscObject>(pattern), &comm));
  PetscInt first = 0, last = 0;
  CATENA_PETSC(MatGetOwnershipRange(pattern, &first, &last));
  m.n_owned = last - first;
  for (const EigenBlock& where : form.blocks) {
    Block block;
    block.where = where;
    if (where.size == 1) {
      CATENA_PETSC(MatDuplicate(pattern, MAT_DO_NOT_COPY_VALUES, block.single.out()));
      CATENA_PETSC(MatCreateVecs(block.single.get(), block.solution.out(), block.rhs.out()));
    } else {
      block.pair = std::make_unique<BlockMatrix>(pattern, 2);
      block.rhs = block.pair->create_vector();
      block.solution = block.pair->create_vector();
    }
    const std::string block_prefix = prefix + "block" + std::to_string(m.blocks.size()) + "_";
    block.ksp = create_direct_ksp(comm, block_prefix, JacobianSymmetry::general, pivoting);
    m.blocks.push_back(std::move(block));
  }
  for (int i = 0; i < m.s; ++i)
    for (std::vector<VecHandle>* v : {&m.x_parts, &m.y_parts, &m.Cx, &m.Kx}) {
      VecHandle x;
      CATENA_PETSC(MatCreateVecs(pattern, x.out(), nullptr));
      v->push_back(std::move(x));
    }
  const PetscInt n_local = m.n_owned * m.s;
  CATENA_PETSC(
      MatCreateShell(comm, n_local, n_local, PETSC_DETERMINE, PETSC_DETERMINE, &m, m.shell.out()));
  CATENA_PETSC(MatShellSetOperation(m.shell.get(), MATOP_MULT,
                                    reinterpret_cast<void (*)(void)>(Impl::shell_mult)));
}

DecoupledStageSolver::~DecoupledStageSolver() = default;

Mat DecoupledStageSolver::operator_matrix() const { return impl_->shell.get(); }

void DecoupledStageSolver::install(KSP ksp, CallbackGuard& guard) {
  impl_->guard = &guard;
  PC pc = nullptr;
  CATENA_PETSC(KSPGetPC(ksp, &pc));
  CATENA_PETSC(PCSetType(pc, PCSHELL));
  CATENA_PETSC(PCShellSetContext(pc, impl_.get()));
  CATENA_PETSC(PCShellSetSetUp(pc, Impl::pc_setup));
  CATENA_PETSC(PCShellSetApply(pc, Impl::pc_apply));
  CATENA_PETSC(PCShellSetName(pc, "decoupled IRK stage solve (RADAU5-style)"));
}

void DecoupledStageSolver::assemble(const StageMatrixParts& parts) {
  Impl& m = *impl_;
  m.parts = parts;
  const double h = parts.h;
  for (Block& block : m.blocks) {
    const int o = block.where.offset;
    if (block.where.size == 1) {
      const double lambda = m.form.D(o, o);
      Mat E = block.single.get();
      CATENA_PETSC(MatCopy(parts.M, E, SAME_NONZERO_PATTERN));
      CATENA_PETSC(MatAXPY(E, h * lambda, parts.C, SAME_NONZERO_PATTERN));
      CATENA_PETSC(MatAXPY(E, h * h * lambda * lambda, parts.K, SAME_NONZERO_PATTERN));
    } else {
      const Eigen::Matrix2d d = m.form.D.block<2, 2>(o, o);
      const Eigen::Matrix2d d2 = d * d;
      BlockCoefficients c(2);
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
          c.M(i, j) = i == j ? 1.0 : 0.0;
          c.C(i, j) = h * d(i, j);
          c.K(i, j) = h * h * d2(i, j);
        }
      block.pair->assemble(parts.K, parts.C, parts.M, c);
    }
    if (parts.row_scale) {
      if (!block.row_scale) CATENA_PETSC(VecDuplicate(block.rhs.get(), block.row_scale.out()));
      std::vector<Vec> copies(static_cast<size_t>(block.where.size), parts.row_scale);
      join_interleaved(copies, block.row_scale.get());
      CATENA_PETSC(MatDiagonalScale(block.matrix(), block.row_scale.get(), nullptr));
    }
  }
  m.factored = false;
  // The operator changed: assembling the shell raises its state, so the PC's next setup
  // refactors every block (PCSetUp compares the operator's state with its own).
  CATENA_PETSC(MatAssemblyBegin(m.shell.get(), MAT_FINAL_ASSEMBLY));
  CATENA_PETSC(MatAssemblyEnd(m.shell.get(), MAT_FINAL_ASSEMBLY));
}

KSP DecoupledStageSolver::real_block(double lambda) {
  Impl& m = *impl_;
  for (Block& block : m.blocks) {
    if (block.where.size != 1) continue;
    const double mu = m.form.D(block.where.offset, block.where.offset);
    if (std::abs(mu - lambda) > 1e-14 * std::abs(lambda)) continue;
    if (!m.factored) m.factor();
    return m.failure.empty() ? block.ksp.get() : nullptr;
  }
  return nullptr;
}

const std::string& DecoupledStageSolver::failure() const { return impl_->failure; }

bool DecoupledStageSolver::solve(Vec r, Vec y) { return impl_->solve(r, y); }

}  // namespace catena::solvers
