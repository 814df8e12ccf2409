// RealtimeClock as realtime_tools noetic-devel 164f6d8 src/realtime_clock.cpp computes it.
#include <realtime_tools/realtime_clock.h>

#include <chrono>

namespace realtime_tools
{

namespace
{
// realtime_clock.cpp l. 61: how often the thread samples the system clock
const double SAMPLE_RATE_HZ = 750.0;
// l. 42: the offset's first-order filter, new sample's weight
const double OFFSET_FILTER_WEIGHT = 0.0001;
// l. 78-79: misses after which the thread warns, at most once a second
const unsigned int LOCK_MISSES_WARNED = 100;
const double WARNING_PERIOD = 1.0;
// l. 69: the thread polls for the lock rather than blocking on it
const std::chrono::microseconds LOCK_POLL_PERIOD(500);
}  // namespace

RealtimeClock::RealtimeClock() : running_(true), thread_(&RealtimeClock::loop, this)
{
}

RealtimeClock::~RealtimeClock()
{
  running_ = false;
  thread_.join();
}

ros::Time RealtimeClock::getSystemTime(const ros::Time& realtime_time)
{
  std::unique_lock<std::mutex> guard(mutex_, std::try_to_lock);
  if (guard.owns_lock())
  {
    // l. 28-43: a fresh sample since the last call moves the offset; half the loop's period
    // stands for when, within it, the sample was taken
    if (lock_misses_ == 0 && system_time_ != ros::Time())
    {
      ros::Duration period_offset;
      if (last_realtime_time_ != ros::Time())
        period_offset = ros::Duration((realtime_time - last_realtime_time_).toSec() / 2.0);
      ros::Duration measured = system_time_ + period_offset - realtime_time;
      if (!initialized_)
      {
        clock_offset_ = measured;
        initialized_ = true;
      }
      else
      {
        clock_offset_ = clock_offset_ * (1.0 - OFFSET_FILTER_WEIGHT) + measured * OFFSET_FILTER_WEIGHT;
      }
    }
    system_time_ = ros::Time();
    lock_misses_ = 0;
  }
  else
  {
    lock_misses_++;
  }
  last_realtime_time_ = realtime_time;
  return realtime_time + clock_offset_;
}

void RealtimeClock::loop()
{
  ros::Rate rate(SAMPLE_RATE_HZ);
  while (running_)
  {
    while (!mutex_.try_lock())
      std::this_thread::sleep_for(LOCK_POLL_PERIOD);
    system_time_ = ros::Time::now();
    if (lock_misses_ > LOCK_MISSES_WARNED)
      ROS_WARN_THROTTLE(WARNING_PERIOD, "Time estimator has trouble transferring data between non-RT and RT");
    mutex_.unlock();
    rate.sleep();
  }
}

}  // namespace realtime_tools
