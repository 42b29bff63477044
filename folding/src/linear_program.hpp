#pragma once
// A thin wrapper over COIN-OR Clp, so that planners state LPs in plain vectors and never include
// Clp's headers (Clp is linked privately).
#include <memory>
#include <utility>
#include <vector>

class ClpSimplex;

namespace foldkit::folding::detail {

// minimise cost·x subject to col_lower <= x <= col_upper and row_lower <= A x <= row_upper, A
// given as (entry_row, entry_col, entry_value) triplets. Bounds may be ±infinity.
struct LinearProgram {
  std::vector<double> col_lower, col_upper, cost;
  std::vector<int> entry_row, entry_col;
  std::vector<double> entry_value;
  std::vector<double> row_lower, row_upper;

  int add_column(double lower, double upper, double cost);
  int add_row(const std::vector<std::pair<int, double>>& coefficients, double lower, double upper);
};

struct LpSolution {
  enum class Status { Optimal, Infeasible, Unbounded, Failed } status = Status::Failed;
  std::vector<double> x;
  double objective = 0.0;
};

// Dual simplex (Clp, log level 0). Throws std::invalid_argument when the LP is malformed
// (index out of range, mismatched vector sizes).
LpSolution solve(const LinearProgram& lp);

// One Clp model kept between solves, for constraint generation: rows added after a solve enter
// with their slacks basic, so the next dual simplex starts from the last optimal basis (still
// dual feasible) instead of from scratch. A basis saved by basis() from a model of the same
// shape may be handed to the next model by set_basis() (Clp repairs one that does not fit).
class IncrementalLp {
 public:
  explicit IncrementalLp(const LinearProgram& lp);  // throws like solve()
  ~IncrementalLp();
  IncrementalLp(const IncrementalLp&) = delete;
  IncrementalLp& operator=(const IncrementalLp&) = delete;

  int rows() const;
  int add_row(const std::vector<std::pair<int, double>>& coefficients, double lower, double upper);
  enum class Method { Dual, Primal };
  // `max_iterations` > 0 stops Clp after that many simplex iterations, with status Failed: a
  // caller that can solve afresh bounds a warm start that stalls.
  LpSolution solve(Method method = Method::Dual, int max_iterations = 0);
  int columns() const { return columns_; }

  struct Basis {
    std::vector<unsigned char> column, row;  // Clp status codes
  };
  Basis basis() const;
  void set_basis(const Basis& basis);  // sizes must match columns and rows

 private:
  std::unique_ptr<ClpSimplex> model_;
  int columns_ = 0;
  std::vector<double> lower_, upper_, elements_;
  std::vector<int> starts_{0}, indices_;
};

const char* to_string(LpSolution::Status status);

}  // namespace foldkit::folding::detail
