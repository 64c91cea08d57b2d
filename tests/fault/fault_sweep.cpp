#include "fault_sweep.hpp"

#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <vector>

namespace fault {
namespace {

const char *g_case = "";
uint64_t g_k = 0;

// The values of k to try for a call that makes `total` allocations.
std::vector<uint64_t> schedule(uint64_t total, uint64_t max_attempts) {
    std::vector<uint64_t> ks;
    if (total <= max_attempts) {
        for (uint64_t k = 1; k <= total; ++k) ks.push_back(k);
        return ks;
    }
    const uint64_t linear = max_attempts / 3;
    for (uint64_t k = 1; k <= linear; ++k) ks.push_back(k);
    const uint64_t left = max_attempts - linear;
    // k grows by a constant factor from `linear` to `total` in `left` steps.
    const double factor = std::pow(static_cast<double>(total) / linear, 1.0 / left);
    double next = static_cast<double>(linear);
    while (ks.back() < total) {
        next *= factor;
        const uint64_t k = static_cast<uint64_t>(next);
        if (k > ks.back()) ks.push_back(k < total ? k : total);
    }
    return ks;
}

// The answer of one call with nothing failing, and how many allocations it
// makes (counted by arming a failure that is never reached).
Record reference_answer(const SweepCase &sweep_case, uint64_t &allocations) {
    std::unique_ptr<Attempt> attempt = sweep_case.make();
    arm(UINT64_MAX, FailMode::kOnce);
    const opx_status status = attempt->call();
    allocations = disarm().allocations;
    Record answer;
    if (status != OPX_OK) {
        std::printf("  %s: the call fails with nothing failing: %s (%s)\n", sweep_case.name.c_str(),
                    opx_status_name(status), opx_last_error());
        return answer;
    }
    attempt->record_answer(answer);
    return answer;
}

class AttemptChecker {
public:
    AttemptChecker(const SweepCase &sweep_case, const Record &reference)
        : case_(sweep_case), reference_(reference) {}

    // Runs the call with its k-th allocation failing; false when done
    // (the call no longer reached the k-th allocation).
    bool run(uint64_t k, FailMode mode) {
        k_ = k;
        std::unique_ptr<Attempt> attempt = case_.make();
        Record before;
        attempt->record_state(before);
        arm(k, mode);
        const opx_status status = attempt->call();
        const ArmedRun run = disarm();
        if (!run.failure_hit) {
            expect_answer(*attempt, status, "a call reaching no failure");
            return false;
        }
        ++failures_hit_;
        if (status == OPX_OK) {  // the library coped without that block
            expect_answer(*attempt, status, "a call that coped with the failure");
            return true;
        }
        check_failure(*attempt, status, run, before);
        expect_answer(*attempt, attempt->call(), "the retry");
        return true;
    }

    int errors() const { return errors_; }
    uint64_t failures_hit() const { return failures_hit_; }

    // Known faults of the case that no attempt met: mended, perhaps.
    void print_unmet_known_faults() const {
        for (const KnownFault &known : case_.known) {
            if (known.kind == KnownFault::kNotChecked) {
                std::printf("  known fault, not checked: %s\n", known.why.c_str());
                continue;
            }
            bool met = false;
            for (const ErrorKind &kind : kinds_) met = met || kind.known == &known;
            if (!met) std::printf("  known fault not met here (mended?): %s\n", known.why.c_str());
        }
    }

    // One line per kind of error: how often, for which k, the first message.
    void print_errors() const {
        for (const ErrorKind &kind : kinds_) {
            std::printf("  %s %s: %llu times, allocations %llu..%llu failing; first (allocation %llu): %s\n",
                        kind.known != nullptr ? "KNOWN" : "FAIL", case_.name.c_str(), static_cast<unsigned long long>(kind.count),
                        static_cast<unsigned long long>(kind.first_k), static_cast<unsigned long long>(kind.last_k),
                        static_cast<unsigned long long>(kind.first_k), kind.first_message.c_str());
        }
    }

private:
    void check_failure(Attempt &attempt, opx_status status, const ArmedRun &run, const Record &before) {
        if (status != OPX_ERROR_OUT_OF_MEMORY)
            error("status", "returned %s, not OPX_ERROR_OUT_OF_MEMORY (last error \"%s\")", opx_status_name(status),
                  opx_last_error());
        else if (std::strstr(opx_last_error(), "out of memory") == nullptr)
            error("message", "last error \"%s\" does not say \"out of memory\"", opx_last_error());
        attempt.use_after_failure();
        Record after;
        attempt.record_state(after);
        if (after != before) error("changed", "the failed call changed its objects: %s", after.first_difference(before).c_str());
        if (attempt.makes_object() && run.live_blocks != 0)
            error("leak", "the failed call kept %lld allocated blocks", static_cast<long long>(run.live_blocks));
    }

    void expect_answer(Attempt &attempt, opx_status status, const char *what) {
        if (status != OPX_OK) {
            error(std::string(what) + " status", "%s returned %s (last error \"%s\")", what, opx_status_name(status), opx_last_error());
            return;
        }
        Record answer;
        attempt.record_answer(answer);
        if (answer != reference_)
            error(std::string(what) + " answer", "%s answers otherwise than a call with nothing failing: %s", what,
                  answer.first_difference(reference_).c_str());
    }

    struct ErrorKind {
        std::string key;
        uint64_t count, first_k, last_k;
        std::string first_message;
        const KnownFault *known;
    };

    __attribute__((format(printf, 3, 4))) void error(const std::string &key, const char *fmt, ...) {
        char text[1024];
        va_list args;
        va_start(args, fmt);
        std::vsnprintf(text, sizeof text, fmt, args);
        va_end(args);
        const KnownFault *known = known_fault(key, text);
        if (known == nullptr) ++errors_;
        const std::string label = known == nullptr ? key : key + " (known: " + known->message_part + ")";
        for (ErrorKind &kind : kinds_) {
            if (kind.key != label) continue;
            ++kind.count;
            kind.last_k = k_;
            return;
        }
        kinds_.push_back(ErrorKind{label, 1, k_, k_, text, known});
    }

    const KnownFault *known_fault(const std::string &key, const char *text) const {
        for (const KnownFault &known : case_.known)
            if (known.kind == key && std::strstr(text, known.message_part.c_str()) != nullptr) return &known;
        return nullptr;
    }

    const SweepCase &case_;
    const Record &reference_;
    uint64_t k_ = 0;
    int errors_ = 0;
    uint64_t failures_hit_ = 0;
    std::vector<ErrorKind> kinds_;
};

}  // namespace

const char *current_case() { return g_case; }
uint64_t current_k() { return g_k; }

bool sweep(const SweepCase &sweep_case, FailMode mode, uint64_t max_attempts) {
    const auto start = std::chrono::steady_clock::now();
    g_case = sweep_case.name.c_str();
    uint64_t total = 0;
    const Record reference = reference_answer(sweep_case, total);
    if (reference.size() == 0) return false;
    AttemptChecker checker(sweep_case, reference);
    uint64_t attempts = 0;
    for (uint64_t k : schedule(total, max_attempts)) {
        g_k = k;
        ++attempts;
        if (!checker.run(k, mode)) break;
    }
    // One past the last allocation: the call must then reach no failure.
    if (attempts == 0 || checker.failures_hit() == attempts) checker.run(total + 1, mode);
    checker.print_errors();
    checker.print_unmet_known_faults();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%-44s %s: %6llu allocations, %5llu tried, %3d errors, %.2f s\n", sweep_case.name.c_str(),
                mode == FailMode::kOnce ? "once" : "from then on", static_cast<unsigned long long>(total),
                static_cast<unsigned long long>(attempts), checker.errors(), seconds);
    std::fflush(stdout);
    return checker.errors() == 0;
}

}  // namespace fault
