#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <vesicle_iga/kernel/derivative.h>

#include <string>
#include <vector>

namespace vesicle_iga
{
  /**
   * Where a field a term reads comes from: the unknowns of the system at
   * the stage of the step (the value level of each field, spec (N2), or
   * the solution of a stationary problem), their rates at the stage, or an
   * auxiliary field on the same mesh that is not an unknown of the system
   * (e.g. the frozen potential psi^n in the phase-field equation).
   */
  enum class FieldSource : unsigned char
  {
    value,
    rate,
    auxiliary
  };

  /// What a term reads at the quadrature points: one derivative of one
  /// scalar component of a field.
  struct FieldInput
  {
    FieldSource  source;
    unsigned int auxiliary;  // which auxiliary field (source auxiliary)
    unsigned int component;  // flat component index of the layout
    unsigned int derivative; // Derivative<dim> index (plain or combined)
    bool
    operator==(const FieldInput &o) const
    {
      return source == o.source && auxiliary == o.auxiliary
             && component == o.component && derivative == o.derivative;
    }
  };

  /// Handles to what a term declared: array indices, fixed at set-up.
  struct InputHandle
  {
    unsigned int index = ~0u;
  };
  struct ResidualHandle
  {
    unsigned int index = ~0u;
  };
  struct JacobianHandle
  {
    unsigned int index = ~0u;
  };

  /**
   * The list every term fills when an assembler is set up: what it
   * reads (FieldInput), to which (test component, derivative of the test
   * function) it adds residual coefficients, and to which (test, trial)
   * derivative pairs it adds Jacobian coefficients. The Jacobian is the
   * derivative of the residual coefficient with respect to a derivative of
   * the trial component's value (FieldSource::value) or of its rate
   * (FieldSource::rate); the assembler applies the time integrator's
   * factors (N4). A term declares into a list of its own, so its handles
   * are the same whichever assembler (or integration) it takes part in;
   * the assembler maps them to shared arrays (equal declarations of several
   * terms share one array).
   */
  template <int dim>
  class TermDeclaration
  {
  public:
    InputHandle
    value(const unsigned int component, const unsigned int derivative)
    {
      return input({FieldSource::value, 0, component, derivative});
    }
    InputHandle
    rate(const unsigned int component, const unsigned int derivative)
    {
      return input({FieldSource::rate, 0, component, derivative});
    }
    InputHandle
    auxiliary(const unsigned int field,
              const unsigned int component,
              const unsigned int derivative)
    {
      return input({FieldSource::auxiliary, field, component, derivative});
    }
    InputHandle
    input(const FieldInput &in);

    ResidualHandle
    residual(const unsigned int test_component,
             const unsigned int test_derivative);

    JacobianHandle
    jacobian(const unsigned int test_component,
             const unsigned int test_derivative,
             const unsigned int trial_component,
             const unsigned int trial_derivative,
             const FieldSource  trial_source = FieldSource::value);

    /// The term needs the physical points x(q) (e.g. for data functions).
    void
    needs_points()
    {
      points = true;
    }

    /// What was declared (read by the assembler).
    struct Residual
    {
      unsigned int component, derivative;
    };
    struct Jacobian
    {
      unsigned int test_component, test_derivative;
      unsigned int trial_component, trial_derivative;
      FieldSource  trial_source;
    };
    std::vector<FieldInput> inputs;
    std::vector<Residual>   residuals;
    std::vector<Jacobian>   jacobians;
    bool                    points = false;
  };


  /**
   * What a term reads on one element (or boundary face): arrays over the
   * quadrature points, one per declared input, and the geometric data of
   * the points. Valid during Term::evaluate().
   */
  template <int dim>
  class QuadratureInputs
  {
  public:
    unsigned int
    size() const
    {
      return n_points;
    }
    const double *
    operator[](const InputHandle h) const
    {
      return data + input_map[h.index] * stride;
    }
    /// Physical point q (if some term declared needs_points()).
    const dealii::Point<dim> &
    point(const unsigned int q) const
    {
      return (*points)[q];
    }
    /// Outward unit normal at point q of a boundary face.
    const dealii::Tensor<1, dim> &
    normal(const unsigned int q) const
    {
      return (*normals)[q];
    }
    /// The element metric tensor G of spec (N1) at point q.
    const dealii::Tensor<2, dim> &
    metric(const unsigned int q) const
    {
      return (*metrics)[q];
    }
    /// The boundary face (deal.II numbering 2 d + side), or -1 on a cell.
    int
    face() const
    {
      return face_number;
    }
    /// The element being assembled.
    unsigned int
    element() const
    {
      return element_index;
    }
    /// Time and time step of the evaluation (t_{n+1} and dt_n in a step).
    double time = 0, time_step = 0;

    // Set by the assembler.
    const double                              *data          = nullptr;
    const unsigned int                        *input_map     = nullptr;
    std::size_t                                stride        = 0;
    unsigned int                               n_points      = 0;
    const std::vector<dealii::Point<dim>>     *points        = nullptr;
    const std::vector<dealii::Tensor<1, dim>> *normals       = nullptr;
    const std::vector<dealii::Tensor<2, dim>> *metrics       = nullptr;
    int                                        face_number   = -1;
    unsigned int                               element_index = 0;
  };


  /**
   * What a term writes on one element: per declared residual and Jacobian
   * an array over the quadrature points to which it adds (+=) its
   * coefficients, without the quadrature weight. With matrix() false the
   * Jacobian arrays are not read and a term may skip them.
   */
  class TermCoefficients
  {
  public:
    double *
    operator[](const ResidualHandle h)
    {
      return residual_data + residual_map[h.index] * stride;
    }
    double *
    operator[](const JacobianHandle h)
    {
      return jacobian_data + jacobian_map[h.index] * stride;
    }
    bool
    matrix() const
    {
      return with_matrix;
    }
    bool
    residual() const
    {
      return with_residual;
    }

    // Set by the assembler.
    double             *residual_data = nullptr, *jacobian_data = nullptr;
    const unsigned int *residual_map = nullptr, *jacobian_map = nullptr;
    std::size_t         stride      = 0;
    bool                with_matrix = true, with_residual = true;
  };


  /**
   * One term of a weak form (a line of (E18), (H14), ...): it declares once
   * what it reads and where it contributes, and on every element adds its
   * residual coefficients and their derivatives (the Jacobian) at all
   * quadrature points at once (one virtual call per element, none per
   * point). The kernel (SystemAssembler) does everything else: evaluation of
   * the fields, integration against the test and trial functions by sum
   * factorisation, scatter. A new term is one class in one file under
   * terms/ (doc/engine.md).
   *
   * Cell terms act on every element; boundary terms (domain() ==
   * boundary) on the boundary faces for which acts_on_face() holds.
   */
  template <int dim>
  class Term
  {
  public:
    enum class Domain
    {
      cell,
      boundary
    };
    virtual ~Term() = default;

    /// Short name (used in messages and in the Jacobian check).
    virtual std::string
    name() const = 0;
    virtual Domain
    domain() const
    {
      return Domain::cell;
    }
    /// Boundary terms: whether face f (2 d + side) of the box has any part
    /// of this term.
    virtual bool
    acts_on_face(const unsigned int /*face*/) const
    {
      return false;
    }
    /// Declare inputs and outputs; the handles are kept by the term. Called
    /// with an empty declaration whenever an assembler is set up: the same
    /// calls in the same order each time.
    virtual void
    declare(TermDeclaration<dim> &declaration)
      = 0;
    /// Add residual (and, if out.matrix(), Jacobian) coefficients at all
    /// points of the element or face.
    virtual void
    evaluate(const QuadratureInputs<dim> &in, TermCoefficients &out) const = 0;
  };


  /**
   * A quantity integrated over the domain (an energy, a constraint
   * functional, a norm): declares its inputs like a term and adds
   * integrand values times the quadrature weights to its sums.
   */
  template <int dim>
  class Integrand
  {
  public:
    virtual ~Integrand() = default;
    /// Number of sums it adds to.
    virtual unsigned int
    n_values() const = 0;
    virtual void
    declare(TermDeclaration<dim> &declaration)
      = 0;
    /// sums[k] += sum_q f_k(q) JxW[q].
    virtual void
    integrate(const QuadratureInputs<dim> &in,
              const double                *JxW,
              double                      *sums) const = 0;
  };


  /**
   * A term that is the first variation of a functional (an energy, a
   * constraint functional): as an Integrand it integrates the functional
   * itself, so that the functional, its variation (residual) and second
   * variation (Jacobian) live in one class.
   */
  template <int dim>
  class FunctionalTerm : public Term<dim>, public Integrand<dim>
  {
  public:
    unsigned int
    n_values() const override
    {
      return 1;
    }
  };
} // namespace vesicle_iga
