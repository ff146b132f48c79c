#include <deal.II/base/timer.h>

#include <vesicle_iga/base/run_context.h>

namespace vesicle_iga
{
  std::unique_ptr<dealii::TimerOutput>
  RunContext::make_timer() const
  {
    // TimerOutput keeps a copy of the stream (its constructor only lacks
    // the const).
    dealii::ConditionalOStream stream = pcout;
    return std::make_unique<dealii::TimerOutput>(
      stream,
      print_details ? dealii::TimerOutput::summary : dealii::TimerOutput::never,
      dealii::TimerOutput::wall_times);
  }
} // namespace vesicle_iga
