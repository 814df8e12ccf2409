// realtime_tools::RealtimeBox (realtime_tools noetic-devel 164f6d8,
// include/realtime_tools/realtime_box.h): one value behind a mutex held only for a copy, so
// both sides may set and get it; a std::shared_ptr inside keeps the copy realtime-safe.
#ifndef REALTIME_TOOLS_REALTIME_BOX_H
#define REALTIME_TOOLS_REALTIME_BOX_H

#include <mutex>

namespace realtime_tools
{

template <class T>
class RealtimeBox
{
public:
  // implicit, as upstream's
  RealtimeBox(const T& initial = T()) : value_(initial)  // NOLINT(runtime/explicit)
  {
  }

  void set(const T& value)
  {
    std::lock_guard<std::mutex> guard(mutex_);
    value_ = value;
  }

  void get(T& ref)
  {
    std::lock_guard<std::mutex> guard(mutex_);
    ref = value_;
  }

private:
  T value_;
  std::mutex mutex_;
};

}  // namespace realtime_tools

#endif  // REALTIME_TOOLS_REALTIME_BOX_H
