#pragma once

#include <vesicle_iga/kernel/forward_ad.h>
#include <vesicle_iga/kernel/term.h>

#include <random>
#include <string>
#include <vector>

namespace vesicle_iga
{
  /// One input of a pointwise formula: a derivative of a component at the
  /// stage (value) or of its rate.
  struct FormulaInput
  {
    unsigned int component, derivative;
    FieldSource  source = FieldSource::value;
  };

  /// One output of a pointwise formula: the coefficient of a derivative of
  /// the test function of a component.
  struct FormulaOutput
  {
    unsigned int component, derivative;
  };


  /**
   * A term given by a pointwise formula: its residual coefficients as a
   * function of its inputs, written once as a template in the number type;
   * the Jacobian coefficients are the exact derivatives by forward-mode
   * automatic differentiation (kernel/forward_ad.h), so a term cannot have
   * a Jacobian that disagrees with its residual. Which (output, input) pairs
   * are non-zero is found when the term is declared, by evaluating the
   * derivatives at random inputs in (-0.9, 0.9); only those pairs are
   * integrated.
   *
   * Formula provides: static constexpr int max_inputs; std::string name();
   * the vectors `inputs` (FormulaInput) and `outputs` (FormulaOutput),
   * filled in its constructor; and
   *   template <typename T> void residual(const T *in, T *out) const,
   * which sets out[0 .. outputs.size()) from in[0 .. inputs.size()).
   */
  template <int dim, class Formula>
  class PointwiseTerm : public Term<dim>
  {
  public:
    explicit PointwiseTerm(const Formula &formula)
      : formula(formula)
    {}

    std::string
    name() const override
    {
      return formula.name();
    }
    /// The formula's parameters may change between assemblies (e.g. the
    /// global multipliers of (H13)), never its inputs and outputs.
    Formula &
    get_formula()
    {
      return formula;
    }
    const Formula &
    get_formula() const
    {
      return formula;
    }

    void
    declare(TermDeclaration<dim> &d) override
    {
      using Number             = Dual<Formula::max_inputs>;
      const unsigned int n_in  = formula.inputs.size();
      const unsigned int n_out = formula.outputs.size();
      AssertThrow(n_in <= Formula::max_inputs, dealii::ExcInternalError());
      input_handles.clear();
      output_handles.clear();
      for (const auto &i : formula.inputs)
        input_handles.push_back(
          d.input({i.source, 0, i.component, i.derivative}));
      for (const auto &o : formula.outputs)
        output_handles.push_back(d.residual(o.component, o.derivative));

      // The non-zero pattern of d out / d in at random inputs.
      std::vector<bool>                      nonzero(n_in * n_out, false);
      std::mt19937                           generator(2024);
      std::uniform_real_distribution<double> uniform(-0.9, 0.9);
      std::vector<Number>                    x(n_in), y(n_out);
      for (unsigned int sample = 0; sample < 4; ++sample)
        {
          for (unsigned int i = 0; i < n_in; ++i)
            x[i] = Number::input(uniform(generator), i);
          formula.residual(x.data(), y.data());
          for (unsigned int o = 0; o < n_out; ++o)
            for (unsigned int i = 0; i < n_in; ++i)
              if (y[o].d[i] != 0)
                nonzero[o * n_in + i] = true;
        }
      jacobian_pairs.clear();
      for (unsigned int o = 0; o < n_out; ++o)
        for (unsigned int i = 0; i < n_in; ++i)
          if (nonzero[o * n_in + i])
            {
              const auto &in  = formula.inputs[i];
              const auto &out = formula.outputs[o];
              jacobian_pairs.push_back({o,
                                        i,
                                        d.jacobian(out.component,
                                                   out.derivative,
                                                   in.component,
                                                   in.derivative,
                                                   in.source)});
            }
    }

    void
    evaluate(const QuadratureInputs<dim> &in,
             TermCoefficients            &out) const override
    {
      const unsigned int n_in  = formula.inputs.size();
      const unsigned int n_out = formula.outputs.size();
      std::array<const double *, Formula::max_inputs> x_data;
      for (unsigned int i = 0; i < n_in; ++i)
        x_data[i] = in[input_handles[i]];
      std::vector<double *> r_data(n_out);
      for (unsigned int o = 0; o < n_out; ++o)
        r_data[o] = out[output_handles[o]];
      if (!out.matrix())
        {
          std::array<double, Formula::max_inputs> x;
          std::vector<double>                     y(n_out);
          for (unsigned int q = 0; q < in.size(); ++q)
            {
              for (unsigned int i = 0; i < n_in; ++i)
                x[i] = x_data[i][q];
              formula.residual(x.data(), y.data());
              for (unsigned int o = 0; o < n_out; ++o)
                r_data[o][q] += y[o];
            }
          return;
        }
      using Number = Dual<Formula::max_inputs>;
      std::array<Number, Formula::max_inputs> x;
      std::vector<Number>                     y(n_out);
      std::vector<double *>                   j_data(jacobian_pairs.size());
      for (unsigned int k = 0; k < jacobian_pairs.size(); ++k)
        j_data[k] = out[jacobian_pairs[k].handle];
      for (unsigned int q = 0; q < in.size(); ++q)
        {
          for (unsigned int i = 0; i < n_in; ++i)
            x[i] = Number::input(x_data[i][q], i);
          formula.residual(x.data(), y.data());
          if (out.residual())
            for (unsigned int o = 0; o < n_out; ++o)
              r_data[o][q] += y[o].v;
          for (unsigned int k = 0; k < jacobian_pairs.size(); ++k)
            j_data[k][q]
              += y[jacobian_pairs[k].output].d[jacobian_pairs[k].input];
        }
    }

  private:
    struct Pair
    {
      unsigned int   output, input;
      JacobianHandle handle;
    };
    Formula                     formula;
    std::vector<InputHandle>    input_handles;
    std::vector<ResidualHandle> output_handles;
    std::vector<Pair>           jacobian_pairs;
  };
} // namespace vesicle_iga
