#include "machine_probe.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <thread>

namespace bench {
namespace {

constexpr uint64_t kIterations = 20000000;
constexpr double kAdditions = 8.0 * kIterations;

// Eight additions an iteration, each into its own register from the last
// iteration's values but one: a core retires several a cycle, so the loop
// runs at the speed of the core's adders.  The empty asm keeps the
// compiler from folding or vectorising the additions.
uint64_t add_loop() {
    uint64_t a = 1, b = 2, c = 3, d = 4, e = 5, f = 6, g = 7, h = 8;
    for (uint64_t i = 0; i < kIterations; ++i) {
        a += b, b += c, c += d, d += e, e += f, f += g, g += h, h += a;
        asm volatile("" : "+r"(a), "+r"(b), "+r"(c), "+r"(d), "+r"(e), "+r"(f), "+r"(g), "+r"(h));
    }
    return a ^ b ^ c ^ d ^ e ^ f ^ g ^ h;
}

template <class Run>
double nanoseconds(Run &&run) {
    const auto start = std::chrono::steady_clock::now();
    run();
    return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

ThreadSpeed measure_thread_speed() {
    volatile uint64_t sink = 0;
    double alone = 1e30, together = 1e30;
    for (int round = 0; round < 3; ++round) {
        alone = std::min(alone, nanoseconds([&] { sink = sink + add_loop(); }));
        together = std::min(together, nanoseconds([&] {
                                std::thread other([&] { sink = sink + add_loop(); });
                                const uint64_t mine = add_loop();
                                other.join();
                                sink = sink + mine;
                            }));
    }
    return ThreadSpeed{kAdditions / alone, kAdditions / together};
}

void print_thread_speeds(const ThreadSpeed &at_start, const ThreadSpeed &at_end) {
    std::printf("integer additions a ns, one thread alone / each of two at once: %.1f / %.1f at the start, "
                "%.1f / %.1f at the end\n(about 13 on a core of its own; half that where the core is shared)\n",
                at_start.one_thread, at_start.each_of_two, at_end.one_thread, at_end.each_of_two);
}

std::string thread_speed_json_fields(const ThreadSpeed &at_start, const ThreadSpeed &at_end) {
    char text[256];
    std::snprintf(text, sizeof text,
                  "\"adds_per_ns_one_thread_at_start\": %.2f, \"adds_per_ns_each_of_two_at_start\": %.2f, "
                  "\"adds_per_ns_one_thread_at_end\": %.2f, \"adds_per_ns_each_of_two_at_end\": %.2f",
                  at_start.one_thread, at_start.each_of_two, at_end.one_thread, at_end.each_of_two);
    return text;
}

}  // namespace bench
