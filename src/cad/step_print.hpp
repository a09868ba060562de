// Printing a STEP model (OpenCASCADE's StepData) on all cores.
#pragma once

#include <StepData_Protocol.hxx>
#include <StepData_StepModel.hxx>
#include <functional>
#include <ostream>

namespace stitch::cad {

/// Prints `model` as OpenCASCADE's STEPControl_Writer::Write does, byte for byte, with ranges of
/// its entities formatted on all cores: each entity's lines name the others by their number in
/// the model and depend on nothing printed before them, so writers of their own format the ranges
/// and their lines are printed in order. `progress`, if given, is called with the share of the
/// entities printed, from one thread at a time. Returns whether `out` took every line.
bool print_step(const Handle(StepData_StepModel) & model,
                const Handle(StepData_Protocol) & protocol, std::ostream& out,
                const std::function<void(double)>& progress = {});

}  // namespace stitch::cad
