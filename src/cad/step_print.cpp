#include "step_print.hpp"

#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>

#include <Interface_Check.hxx>
#include <StepData_StepWriter.hxx>
#include <StepData_WriterLib.hxx>
#include <algorithm>
#include <cstdint>
#include <memory>

namespace stitch::cad {

bool print_step(const Handle(StepData_StepModel) & model,
                const Handle(StepData_Protocol) & protocol, std::ostream& out,
                const std::function<void(double)>& progress) {
  // StepData_StepWriter::SendModel's sections, the entities' part in ranges.
  out << "ISO-10303-21;\n";  // SendModel leaves it out of a header alone
  StepData_StepWriter header(model);
  header.SendModel(protocol, Standard_True);
  header.SendData();
  const Handle(Interface_Check) global = model->GlobalCheck();
  if (global->NbFails() > 0) {
    header.Comment(Standard_True);
    header.SendComment("GLOBAL FAIL MESSAGES,  recorded at Read time :");
    for (int i = 1; i <= global->NbFails(); ++i) header.SendComment(global->Fail(i));
    header.Comment(Standard_False);
    header.NewLine(Standard_False);
  }
  if (!header.Print(out)) return false;

  // Ranges formatted on all cores and printed in order as they are done, so only a few ranges'
  // lines are held at a time.
  constexpr int kEntitiesPerRange = 4096;
  const int entities = model->NbEntities();
  struct Range {
    int first = 0, end = 0;
    std::unique_ptr<StepData_StepWriter> writer;
    std::unique_ptr<StepData_WriterLib> library;
  };
  int next = 1;
  bool printed = true;
  tbb::parallel_pipeline(
      2 * static_cast<size_t>(tbb::this_task_arena::max_concurrency()),
      tbb::make_filter<void, std::shared_ptr<Range>>(
          tbb::filter_mode::serial_in_order,
          [&](tbb::flow_control& control) {
            if (next > entities || !printed) {
              control.stop();
              return std::shared_ptr<Range>();
            }
            auto range = std::make_shared<Range>();
            range->first = next;
            range->end = next = std::min(entities + 1, next + kEntitiesPerRange);
            range->writer = std::make_unique<StepData_StepWriter>(model);
            // The library's constructor keeps the last protocol in statics: made on one thread.
            range->library = std::make_unique<StepData_WriterLib>(protocol);
            return range;
          }) &
          tbb::make_filter<std::shared_ptr<Range>, std::shared_ptr<Range>>(
              tbb::filter_mode::parallel,
              [](std::shared_ptr<Range> range) {
                for (int i = range->first; i < range->end; ++i)
                  range->writer->SendEntity(i, *range->library);
                return range;
              }) &
          tbb::make_filter<std::shared_ptr<Range>, void>(
              tbb::filter_mode::serial_in_order, [&](std::shared_ptr<Range> range) {
                printed = printed && range->writer->Print(out);
                if (progress) progress(double(range->end - 1) / entities);
              }));
  if (!printed) return false;
  StepData_StepWriter end(model);
  end.EndSec();
  end.EndFile();
  return end.Print(out);
}

}  // namespace stitch::cad
