// realtime_tools::RealtimeClock (realtime_tools noetic-devel 164f6d8,
// include/realtime_tools/realtime_clock.h, src/realtime_clock.cpp): the system time as seen
// from a realtime loop that must not call the clock itself. A thread samples ros::Time::now()
// at 750 Hz; getSystemTime(realtime_time) returns realtime_time plus an offset filtered from
// those samples.
#ifndef REALTIME_TOOLS_REALTIME_CLOCK_H
#define REALTIME_TOOLS_REALTIME_CLOCK_H

#include <ros/ros.h>

#include <atomic>
#include <mutex>
#include <thread>

namespace realtime_tools
{

class RealtimeClock
{
public:
  RealtimeClock();
  ~RealtimeClock();

  ros::Time getSystemTime(const ros::Time& realtime_time);
  void loop();

private:
  unsigned int lock_misses_ = 0;
  ros::Time system_time_;
  ros::Duration clock_offset_;
  ros::Time last_realtime_time_;
  std::atomic<bool> running_{false};
  bool initialized_ = false;
  std::mutex mutex_;
  std::thread thread_;
};

}  // namespace realtime_tools

#endif  // REALTIME_TOOLS_REALTIME_CLOCK_H
