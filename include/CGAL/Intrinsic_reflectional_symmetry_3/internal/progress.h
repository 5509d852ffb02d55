// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_PROGRESS_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_PROGRESS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>
#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <functional>
#include <mutex>
#include <string>
#include <utility>

// The `callback` named parameter, as CGAL's Point_set_processing_3 and
// Shape_detection read it: a `bool(double)` called with the advancement of
// the function, in [0, 1]; returning false stops the function, which then
// throws Operation_cancelled. Worker threads report what they finish; the
// calls are serialised (a thread that finds another one calling skips its
// report), so the callback need not be thread-safe, and the advancement
// it sees never decreases. A callback never changes a result.

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

class Progress
{
public:
  typedef std::function<bool(double)> Callback;

  /// `stage` names the function in the message of Operation_cancelled
  Progress(Callback callback, std::string stage) : callback_(std::move(callback)), stage_(std::move(stage)) {}
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  bool active() const { return bool(callback_); }

  /// whether the callback asked to stop (workers skip the rest of their work)
  bool stopped() const { return stopped_.load(std::memory_order_relaxed); }

  /// reports `value` (clamped to [0, 1]) unless a larger value was reported;
  /// from a worker (`wait` false), not if another thread is reporting
  void report(double value, bool wait = false)
  {
    if(!callback_ || stopped()) return;
    std::unique_lock<std::mutex> lock(mutex_, std::defer_lock);
    if(wait) lock.lock();
    else if(!lock.try_lock()) return;
    if(stopped()) return;
    value = (std::min)(1., (std::max)(0., value));
    if(value <= last_) return;
    last_ = value;
    if(!callback_(value)) stopped_.store(true, std::memory_order_relaxed);
  }

  /// throws Operation_cancelled if the callback asked to stop
  void check() const
  {
    if(stopped()) throw Operation_cancelled("cancelled by the callback during " + stage_);
  }

  /// reports `value` from sequential code (outside parallel loops), then check()
  void step(double value)
  {
    report(value, true);
    check();
  }

private:
  Callback callback_;
  std::string stage_;
  std::atomic<bool> stopped_{false};
  std::mutex mutex_;
  double last_ = -1.;
};

/// Counts the units of work of a (parallel) loop that covers [from, to] of
/// the whole, and reports the advancement at most 100 times over the loop.
class Progress_counter
{
public:
  Progress_counter(Progress& p, double from, double to, std::size_t total)
    : p_(p), from_(from), to_(to), total_((std::max)(total, std::size_t(1))),
      stride_((std::max)(total_ / 100, std::size_t(1)))
  {}

  bool stopped() const { return p_.stopped(); }

  void advance(std::size_t n = 1)
  {
    if(!p_.active()) return;
    const std::size_t before = done_.fetch_add(n, std::memory_order_relaxed);
    if((before + n) / stride_ != before / stride_ || before + n >= total_)
      p_.report(from_ + (to_ - from_) * double((std::min)(before + n, total_)) / double(total_));
  }

private:
  Progress& p_;
  double from_, to_;
  std::size_t total_, stride_;
  std::atomic<std::size_t> done_{0};
};

/// the `callback` of a named parameter pack (an empty function if absent)
template <class NamedParameters>
Progress::Callback progress_callback(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  return choose_parameter(get_parameter(np, CGAL::internal_np::callback), Progress::Callback());
}

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_PROGRESS_H
