// A value computed on first request and kept until reset(), for const
// getters that compute a costly diagnostic only when asked.  get() may run
// from several threads at once on the same object (the first computes, the
// others wait and read its value), as const calls of the C ABI may; reset()
// and assignment belong to the owner's non-const calls.  Copies and moves
// carry the value, so an owner stays copyable and (without throwing) movable.
#pragma once

#include <mutex>
#include <type_traits>
#include <utility>

namespace octoprox {

template <class T>
class LazyValue {
    static_assert(std::is_nothrow_move_constructible_v<T> && std::is_nothrow_move_assignable_v<T>,
                  "moves must not throw");

public:
    LazyValue() = default;
    LazyValue(const LazyValue &other) {
        std::lock_guard<std::mutex> lock(other.mutex_);
        value_ = other.value_;
        valid_ = other.valid_;
    }
    // A move changes the source: no other thread may be reading either.
    LazyValue(LazyValue &&other) noexcept : value_(std::move(other.value_)), valid_(other.valid_) {}
    LazyValue &operator=(LazyValue &&other) noexcept {
        value_ = std::move(other.value_);
        valid_ = other.valid_;
        return *this;
    }
    LazyValue &operator=(const LazyValue &other) {
        if (this == &other) return *this;
        std::scoped_lock lock(mutex_, other.mutex_);
        value_ = other.value_;
        valid_ = other.valid_;
        return *this;
    }

    // compute() runs at most once until the next reset(); if it throws,
    // nothing is kept and the next get() tries again.
    template <class Compute>
    T get(Compute &&compute) const {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!valid_) {
            value_ = compute();
            valid_ = true;
        }
        return value_;
    }

    void reset() {
        std::lock_guard<std::mutex> lock(mutex_);
        valid_ = false;
    }

private:
    mutable std::mutex mutex_;
    mutable T value_{};
    mutable bool valid_ = false;
};

}  // namespace octoprox
