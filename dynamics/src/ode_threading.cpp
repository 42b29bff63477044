#include "ode_threading.hpp"

#include <new>
#include <utility>

#include "ode_sheet.hpp"

namespace foldkit::dynamics::detail {

StepThreading::StepThreading() : ode_(dThreadingAllocateSelfThreadedImplementation()) {
  if (!ode_) throw std::bad_alloc();
  ode_functions_ = dThreadingImplementationGetFunctions(ode_);
  forward_functions();
}

StepThreading::~StepThreading() { dThreadingFreeImplementation(ode_); }

void StepThreading::attach(dWorldID world) {
  dWorldSetStepThreadingImplementation(world, &functions_, reinterpret_cast<dThreadingImplementationID>(this));
}

void StepThreading::step(dWorldID world, int (*stepper)(dWorldID, dReal), double seconds) {
  // Every call of a step has run when it returns (a self-threaded implementation runs them while
  // the step waits for them), so the records of the last one can go.
  calls_.clear();
  error_ = nullptr;
  const int done = stepper(world, seconds);
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
  if (!done) throw EngineError("ODE could not step the world (out of memory for its step)");
}

int StepThreading::run_call(void* call, dcallindex_t index, dCallReleaseeID releasee) {
  const Call& c = *static_cast<const Call*>(call);
  try {
    return c.function(c.context, index, releasee);
  } catch (...) {
    // A fault, as a call that failed: ODE releases the call and what waits on it, and the step
    // returns; step() then rethrows.
    if (!c.owner->error_) c.owner->error_ = std::current_exception();
    return 0;
  }
}

// Each function forwards to ODE's implementation; post_call wraps the call in run_call().
void StepThreading::forward_functions() {
  functions_ = *ode_functions_;
  functions_.alloc_mutex_group = [](dThreadingImplementationID id, dmutexindex_t count, const char* const* names) {
    return of(id).ode_functions_->alloc_mutex_group(of(id).ode_, count, names);
  };
  functions_.free_mutex_group = [](dThreadingImplementationID id, dMutexGroupID group) {
    of(id).ode_functions_->free_mutex_group(of(id).ode_, group);
  };
  functions_.lock_group_mutex = [](dThreadingImplementationID id, dMutexGroupID group, dmutexindex_t index) {
    of(id).ode_functions_->lock_group_mutex(of(id).ode_, group, index);
  };
  functions_.unlock_group_mutex = [](dThreadingImplementationID id, dMutexGroupID group, dmutexindex_t index) {
    of(id).ode_functions_->unlock_group_mutex(of(id).ode_, group, index);
  };
  functions_.alloc_call_wait = [](dThreadingImplementationID id) { return of(id).ode_functions_->alloc_call_wait(of(id).ode_); };
  functions_.reset_call_wait = [](dThreadingImplementationID id, dCallWaitID wait) {
    of(id).ode_functions_->reset_call_wait(of(id).ode_, wait);
  };
  functions_.free_call_wait = [](dThreadingImplementationID id, dCallWaitID wait) {
    of(id).ode_functions_->free_call_wait(of(id).ode_, wait);
  };
  functions_.post_call = [](dThreadingImplementationID id, int* fault, dCallReleaseeID* releasee, ddependencycount_t dependencies,
                            dCallReleaseeID dependent, dCallWaitID wait, dThreadedCallFunction* function, void* context,
                            dcallindex_t index, const char* name) {
    StepThreading& self = of(id);
    self.calls_.push_back({&self, function, context});
    self.ode_functions_->post_call(self.ode_, fault, releasee, dependencies, dependent, wait, &run_call, &self.calls_.back(), index,
                                   name);
  };
  functions_.alter_call_dependencies_count = [](dThreadingImplementationID id, dCallReleaseeID releasee, ddependencychange_t change) {
    of(id).ode_functions_->alter_call_dependencies_count(of(id).ode_, releasee, change);
  };
  functions_.wait_call = [](dThreadingImplementationID id, int* status, dCallWaitID wait, const dThreadedWaitTime* timeout,
                            const char* name) { of(id).ode_functions_->wait_call(of(id).ode_, status, wait, timeout, name); };
  functions_.retrieve_thread_count = [](dThreadingImplementationID id) {
    return of(id).ode_functions_->retrieve_thread_count(of(id).ode_);
  };
  functions_.preallocate_resources_for_calls = [](dThreadingImplementationID id, ddependencycount_t calls) {
    return of(id).ode_functions_->preallocate_resources_for_calls(of(id).ode_, calls);
  };
}

}  // namespace foldkit::dynamics::detail
