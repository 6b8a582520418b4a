#include "constraints/step_report.h"

#include <iomanip>
#include <sstream>

#include "constraints/dense_system.h"

namespace lamina {
namespace {

const Eigen::IOFormat matrix_format(6, 0, "  ", "\n", "  [", "]");

void print_matrix(std::ostringstream& out, const char* title, const Eigen::MatrixXd& m) {
  out << title << " (" << m.rows() << " × " << m.cols() << ")\n" << m.format(matrix_format) << "\n";
}

void print_rows(std::ostringstream& out, const StepReport& report) {
  // 13 columns per value; the titles are spaced by hand (setw counts bytes, not characters)
  out << "row  Jmap               ζ            η        "
         "   λ⁻           λ⁺        λ_exp            λ            W\n";
  for (size_t i = 0; i < report.mlcp.rows.size(); ++i) {
    const ConstraintRow& row = report.mlcp.rows[i];
    const auto [lo, hi] = row_bounds(row, report.solution.lambda);
    out << std::setw(3) << i << "  {" << std::setw(2) << row.Jmap[0] << "," << std::setw(2)
        << row.Jmap[1] << "}";
    for (double value : {row.zeta, report.mlcp.eta[i], lo, hi, report.lambda_exp[i],
                         report.solution.lambda[i], report.W[i]}) {
      out << "  " << std::setw(11) << value;
    }
    out << "\n";
  }
}

}  // namespace

std::string format_step_report(const StepReport& report) {
  std::ostringstream out;
  out.precision(6);
  const Eigen::MatrixXd J = dense_jacobian(report.mlcp.rows, report.mlcp.body_count);
  print_matrix(out, "J", J);
  // the text's Convert: Bᵀ = J M⁻¹, stored as Bsp
  const Eigen::MatrixXd Bt = dense_b_transpose(report.mlcp);
  print_matrix(out, "Bᵀ = J M⁻¹", Bt);
  // eq. 3-16: J B = J (Bᵀ)ᵀ
  print_matrix(out, "J B", J * Bt.transpose());
  print_rows(out, report);
  out << "PGS sweeps " << report.solution.iterations << ", residual ‖W‖ after each:";
  for (double r : report.solution.residuals) out << " " << r;
  out << "\n";
  return out.str();
}

}  // namespace lamina
