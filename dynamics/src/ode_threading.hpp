#pragma once
// How an OdeSheet's world steps (private to this library, like every file that sees ODE).
//
// ODE runs a world step as calls on a threading implementation's job list; the world's default
// is one implementation shared by the whole process. foldkit's error handlers throw from inside
// those calls (ode_sheet.cpp: an engine error becomes the report's `singular` status), and an
// exception that unwinds through ODE's scheduler loses the job being run (80 bytes per engine
// error) and leaves the job waiting on it in the shared list for good. StepThreading gives one
// world its own implementation of ODE's kind (self-threaded: every call runs on the stepping
// thread), with each call wrapped: an exception stops at the wrapper, the call reports a fault,
// ODE's scheduler releases its jobs as after any failed call, and step() rethrows the exception
// once the step has returned. Nothing is lost, and worlds stepped on two threads share no list.
// The wrapping relies on the implementation being self-threaded: `calls_` and `error_` are not
// locked, so a pooled (multi-threaded) implementation in its place would need both guarded.
#include <deque>
#include <exception>

#include <ode/ode.h>

namespace foldkit::dynamics::detail {

class StepThreading {
 public:
  // ODE must be initialised (EngineScope, ode_sheet.cpp).
  StepThreading();
  // Frees the implementation: after every world attached to it is destroyed.
  ~StepThreading();
  StepThreading(const StepThreading&) = delete;
  StepThreading& operator=(const StepThreading&) = delete;

  // Makes `world` step on this implementation (before its first step).
  void attach(dWorldID world);
  // One step of `world` by `stepper` (dWorldStep or dWorldQuickStep). Rethrows the first
  // exception a call of the step threw (an EngineError from foldkit's handlers), after ODE has
  // finished the step; throws EngineError when the step failed without one.
  void step(dWorldID world, int (*stepper)(dWorldID, dReal), double seconds);

 private:
  // One posted call: ODE's function and context, run by run_call().
  struct Call {
    StepThreading* owner;
    dThreadedCallFunction* function;
    void* context;
  };
  static int run_call(void* call, dcallindex_t index, dCallReleaseeID releasee);
  static StepThreading& of(dThreadingImplementationID id) { return *reinterpret_cast<StepThreading*>(id); }
  void forward_functions();

  dThreadingImplementationID ode_;             // ODE's self-threaded implementation
  const dThreadingFunctionsInfo* ode_functions_;
  dThreadingFunctionsInfo functions_{};        // ode_functions_, each forwarding, post_call wrapping
  std::deque<Call> calls_;                     // this step's calls (a deque: posting keeps addresses)
  std::exception_ptr error_;                   // the first exception of this step's calls
};

}  // namespace foldkit::dynamics::detail
