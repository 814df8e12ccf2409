// realtime_tools::RealtimeBuffer (realtime_tools noetic-devel 164f6d8,
// include/realtime_tools/realtime_buffer.h): a value written from a non-realtime thread and
// read from the realtime loop without ever blocking it. Two copies; the writer fills the
// spare one and flags it, the reader swaps it in when it can take the lock at once and
// otherwise keeps reading the copy it has.
#ifndef REALTIME_TOOLS_REALTIME_BUFFER_H
#define REALTIME_TOOLS_REALTIME_BUFFER_H

#include <chrono>
#include <mutex>
#include <thread>

namespace realtime_tools
{

template <class T>
class RealtimeBuffer
{
public:
  RealtimeBuffer() : realtime_data_(new T()), non_realtime_data_(new T())
  {
  }

  // for types without a default constructor: both copies start as data
  // implicit, as upstream's
  RealtimeBuffer(const T& data)  // NOLINT(runtime/explicit)
    : realtime_data_(new T(data)), non_realtime_data_(new T(data))
  {
  }

  RealtimeBuffer(const RealtimeBuffer& source) : realtime_data_(new T()), non_realtime_data_(new T())
  {
    writeFromNonRT(*source.readFromNonRT());
  }

  RealtimeBuffer& operator=(const RealtimeBuffer& source)
  {
    if (this != &source)
      writeFromNonRT(*source.readFromNonRT());
    return *this;
  }

  ~RealtimeBuffer()
  {
    delete realtime_data_;
    delete non_realtime_data_;
  }

  // Realtime side: never waits. The newest written value if the writer is not busy,
  // the previous one otherwise.
  T* readFromRT()
  {
    std::unique_lock<std::mutex> guard(mutex_, std::try_to_lock);
    if (guard.owns_lock() && new_data_available_)
    {
      std::swap(realtime_data_, non_realtime_data_);
      new_data_available_ = false;
    }
    return realtime_data_;
  }

  // Non-realtime side: the newest value, written or already swapped in
  T* readFromNonRT() const
  {
    std::lock_guard<std::mutex> guard(mutex_);
    return new_data_available_ ? non_realtime_data_ : realtime_data_;
  }

  void writeFromNonRT(const T& data)
  {
    lockPolling();
    *non_realtime_data_ = data;
    new_data_available_ = true;
    mutex_.unlock();
  }

  // both copies at once, before the realtime loop runs
  void initRT(const T& data)
  {
    *non_realtime_data_ = data;
    *realtime_data_ = data;
  }

private:
  // upstream's writer polls for the lock (every 500 us) rather than blocking on it, so that
  // a realtime reader holding it never waits on a priority inversion
  void lockPolling()
  {
    static const std::chrono::microseconds poll_period(500);
    while (!mutex_.try_lock())
      std::this_thread::sleep_for(poll_period);
  }

  T* realtime_data_;
  T* non_realtime_data_;
  bool new_data_available_{false};
  mutable std::mutex mutex_;
};

}  // namespace realtime_tools

#endif  // REALTIME_TOOLS_REALTIME_BUFFER_H
