#include "linear_program.hpp"

#include <ClpSimplex.hpp>
#include <CoinPackedMatrix.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace foldkit::folding::detail {

namespace {

// Clp marks infinite bounds by COIN_DBL_MAX; std::numeric_limits infinity is mapped to it.
double clp_bound(double value) {
  if (std::isinf(value)) return value > 0 ? COIN_DBL_MAX : -COIN_DBL_MAX;
  return value;
}

void check_shape(const LinearProgram& lp) {
  const std::size_t columns = lp.cost.size();
  if (lp.col_lower.size() != columns || lp.col_upper.size() != columns)
    throw std::invalid_argument("LinearProgram: column bounds and cost differ in size");
  if (lp.row_lower.size() != lp.row_upper.size())
    throw std::invalid_argument("LinearProgram: row bounds differ in size");
  if (lp.entry_row.size() != lp.entry_col.size() || lp.entry_row.size() != lp.entry_value.size())
    throw std::invalid_argument("LinearProgram: entry triplets differ in size");
  const auto rows = static_cast<int>(lp.row_lower.size());
  for (std::size_t k = 0; k < lp.entry_row.size(); ++k) {
    if (lp.entry_row[k] < 0 || lp.entry_row[k] >= rows || lp.entry_col[k] < 0 ||
        lp.entry_col[k] >= static_cast<int>(columns))
      throw std::invalid_argument("LinearProgram: entry " + std::to_string(k) + " out of range");
    if (!std::isfinite(lp.entry_value[k]))
      throw std::invalid_argument("LinearProgram: entry " + std::to_string(k) + " is not finite");
  }
}

}  // namespace

int LinearProgram::add_column(double lower, double upper, double c) {
  col_lower.push_back(lower);
  col_upper.push_back(upper);
  cost.push_back(c);
  return static_cast<int>(cost.size()) - 1;
}

int LinearProgram::add_row(const std::vector<std::pair<int, double>>& coefficients, double lower,
                           double upper) {
  const auto row = static_cast<int>(row_lower.size());
  for (const auto& [column, value] : coefficients) {
    entry_row.push_back(row);
    entry_col.push_back(column);
    entry_value.push_back(value);
  }
  row_lower.push_back(lower);
  row_upper.push_back(upper);
  return row;
}

LpSolution solve(const LinearProgram& lp) { return IncrementalLp(lp).solve(); }

IncrementalLp::IncrementalLp(const LinearProgram& lp) : model_(std::make_unique<ClpSimplex>()) {
  check_shape(lp);
  columns_ = static_cast<int>(lp.cost.size());
  const auto rows = static_cast<int>(lp.row_lower.size());
  const auto entries = static_cast<int>(lp.entry_value.size());

  std::vector<double> col_lower(lp.col_lower), col_upper(lp.col_upper);
  std::vector<double> row_lower(lp.row_lower), row_upper(lp.row_upper);
  for (auto* bounds : {&col_lower, &col_upper, &row_lower, &row_upper})
    for (double& b : *bounds) b = clp_bound(b);

  // Triplets may repeat a (row, column) pair; CoinPackedMatrix would reject duplicates, so they
  // are summed, as a sparse-row reading of the LP implies.
  CoinPackedMatrix matrix(false, lp.entry_row.data(), lp.entry_col.data(), lp.entry_value.data(),
                          entries);
  matrix.setDimensions(rows, columns_);
  matrix.removeGaps();

  model_->setLogLevel(0);
  model_->loadProblem(matrix, col_lower.data(), col_upper.data(), lp.cost.data(), row_lower.data(),
                      row_upper.data());
  model_->setOptimizationDirection(1.0);
  model_->createStatus();  // the all-slack basis, so that basis() always has one to give
}

IncrementalLp::~IncrementalLp() = default;

int IncrementalLp::rows() const { return model_->numberRows() + static_cast<int>(lower_.size()); }

int IncrementalLp::add_row(const std::vector<std::pair<int, double>>& coefficients, double lower,
                           double upper) {
  // Summed by column, like the triplets of LinearProgram: Clp rejects a row naming one twice.
  std::vector<std::pair<int, double>> row(coefficients);
  for (std::size_t k = 0; k < row.size(); ++k)
    if (row[k].first < 0 || row[k].first >= columns_ || !std::isfinite(row[k].second))
      throw std::invalid_argument("IncrementalLp: row entry " + std::to_string(k) +
                                  " out of range or not finite");
  std::stable_sort(row.begin(), row.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  for (std::size_t k = 0; k < row.size(); ++k) {
    if (!indices_.empty() && static_cast<int>(indices_.size()) > starts_.back() &&
        indices_.back() == row[k].first)
      elements_.back() += row[k].second;
    else {
      indices_.push_back(row[k].first);
      elements_.push_back(row[k].second);
    }
  }
  starts_.push_back(static_cast<int>(indices_.size()));
  lower_.push_back(clp_bound(lower));
  upper_.push_back(clp_bound(upper));
  return rows() - 1;
}

LpSolution IncrementalLp::solve(Method method, int max_iterations) {
  if (!lower_.empty()) {
    model_->addRows(static_cast<int>(lower_.size()), lower_.data(), upper_.data(), starts_.data(),
                    indices_.data(), elements_.data());
    lower_.clear();
    upper_.clear();
    elements_.clear();
    indices_.clear();
    starts_.assign(1, 0);
  }
  const int default_limit = model_->maximumIterations();
  if (max_iterations > 0) model_->setMaximumIterations(max_iterations);
  if (method == Method::Primal)
    model_->primal();
  else
    model_->dual();
  model_->setMaximumIterations(default_limit);

  LpSolution solution;
  switch (model_->status()) {
    case 0: solution.status = LpSolution::Status::Optimal; break;
    case 1: solution.status = LpSolution::Status::Infeasible; break;
    case 2: solution.status = LpSolution::Status::Unbounded; break;
    default: solution.status = LpSolution::Status::Failed; break;
  }
  if (solution.status == LpSolution::Status::Optimal) {
    const double* x = model_->primalColumnSolution();
    solution.x.assign(x, x + columns_);
    solution.objective = model_->objectiveValue();
  }
  return solution;
}

IncrementalLp::Basis IncrementalLp::basis() const {
  Basis b;
  const unsigned char* status = model_->statusArray();
  if (status == nullptr) return b;
  b.column.assign(status, status + model_->numberColumns());
  b.row.assign(status + model_->numberColumns(), status + model_->numberColumns() + model_->numberRows());
  return b;
}

void IncrementalLp::set_basis(const Basis& basis) {
  if (static_cast<int>(basis.column.size()) != model_->numberColumns() ||
      static_cast<int>(basis.row.size()) != model_->numberRows())
    throw std::invalid_argument("IncrementalLp: basis does not match the model's shape");
  if (model_->statusArray() == nullptr) model_->createStatus();
  for (int j = 0; j < model_->numberColumns(); ++j)
    model_->setColumnStatus(j, static_cast<ClpSimplex::Status>(basis.column[j] & 7));
  for (int i = 0; i < model_->numberRows(); ++i)
    model_->setRowStatus(i, static_cast<ClpSimplex::Status>(basis.row[i] & 7));
}

const char* to_string(LpSolution::Status status) {
  switch (status) {
    case LpSolution::Status::Optimal: return "optimal";
    case LpSolution::Status::Infeasible: return "infeasible";
    case LpSolution::Status::Unbounded: return "unbounded";
    case LpSolution::Status::Failed: return "failed";
  }
  return "failed";
}

}  // namespace foldkit::folding::detail
