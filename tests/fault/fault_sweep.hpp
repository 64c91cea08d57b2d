// The malloc-failure sweep: a call is made with its k-th allocation failing,
// for k = 1, 2, 3, ... until the call no longer reaches the k-th allocation.
// Each failed call must return OPX_ERROR_OUT_OF_MEMORY with a message, and
// leave its objects as they were; a retry on the same objects must then
// answer what a never-failed call answers.
#pragma once

#include "fault_alloc.hpp"
#include "fault_record.hpp"

#include <octoprox/common.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace fault {

// One call under test with its objects, made anew for every k.
class Attempt {
public:
    virtual ~Attempt() = default;
    // The call under test (the failing allocator is armed around it).
    virtual opx_status call() = 0;
    // What a failed call must leave unchanged.
    virtual void record_state(Record &record) = 0;
    // What a successful call answered.
    virtual void record_answer(Record &record) = 0;
    // Reads what a failed call's objects hold (no answer is expected, but
    // nothing may crash).
    virtual void use_after_failure() {}
    // True for calls that make a new object: a failed one must free every
    // block it allocated.
    virtual bool makes_object() const { return false; }
};

using AttemptFactory = std::function<std::unique_ptr<Attempt>()>;

// A library fault the sweep finds and that is not mended yet: its errors
// are printed as KNOWN and do not fail the case.  An error matches when its
// kind is `kind` ("status", "changed", "leak", ...) and its message holds
// `message_part`.  A fault the sweep steps around instead (a crash) has the
// kind kNotChecked.
struct KnownFault {
    static constexpr const char *kNotChecked = "not checked";
    std::string kind;
    std::string message_part;
    std::string why;
};

struct SweepCase {
    std::string name;
    AttemptFactory make;
    std::vector<KnownFault> known = {};
};

// Sweeps one case; prints what it found.  True when every attempt passed.
// At most `max_attempts` values of k are tried: all of them when the call
// makes fewer allocations, else every k up to a third of the budget and
// then k growing geometrically to the last allocation.
bool sweep(const SweepCase &sweep_case, FailMode mode, uint64_t max_attempts);

// The case and k being tried, for the crash handler.
const char *current_case();
uint64_t current_k();

}  // namespace fault
