// realtime_tools::RealtimePublisher (realtime_tools noetic-devel 164f6d8,
// include/realtime_tools/realtime_publisher.h): publishing from a realtime loop. The loop
// writes msg_ between trylock() (which never waits, and fails while the previous message is
// still being sent) and unlockAndPublish(); a thread of the publisher's own copies msg_ and
// publishes it. Messages written while the thread is busy are dropped, as upstream's.
#ifndef REALTIME_TOOLS_REALTIME_PUBLISHER_H
#define REALTIME_TOOLS_REALTIME_PUBLISHER_H

#include <ros/node_handle.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace realtime_tools
{

template <class Msg>
class RealtimePublisher
{
public:
  // What the realtime loop fills between trylock() and unlockAndPublish()
  Msg msg_;

  RealtimePublisher(const ros::NodeHandle& node, const std::string& topic, int queue_size, bool latched = false)
  {
    init(node, topic, queue_size, latched);
  }

  RealtimePublisher()
  {
  }

  RealtimePublisher(const RealtimePublisher&) = delete;
  RealtimePublisher& operator=(const RealtimePublisher&) = delete;

  ~RealtimePublisher()
  {
    stop();
    if (thread_.joinable())
      thread_.join();
    publisher_.shutdown();
  }

  // advertise topic on node's namespace and start the publishing thread
  void init(const ros::NodeHandle& node, const std::string& topic, int queue_size, bool latched = false)
  {
    node_ = node;
    topic_ = topic;
    publisher_ = node_.advertise<Msg>(topic_, queue_size, latched);
    keep_running_ = true;
    turn_ = REALTIME;
    thread_ = std::thread(&RealtimePublisher::publishingLoop, this);
  }

  void stop()
  {
    keep_running_ = false;
  }

  // true when msg_ is the realtime side's to write: the lock was free and the last message
  // has been sent; then unlockAndPublish() (or unlock()) must follow
  bool trylock()
  {
    if (!msg_mutex_.try_lock())
      return false;
    if (turn_ == REALTIME)
      return true;
    msg_mutex_.unlock();
    return false;
  }

  void unlockAndPublish()
  {
    turn_ = NON_REALTIME;
    unlock();
  }

  // the non-realtime side's lock: polls, never blocks (upstream's default build)
  void lock()
  {
    while (!msg_mutex_.try_lock())
      std::this_thread::sleep_for(std::chrono::microseconds(LOCK_POLL_US));
  }

  void unlock()
  {
    msg_mutex_.unlock();
  }

private:
  enum Turn { REALTIME, NON_REALTIME, LOOP_NOT_STARTED };
  // upstream's polling periods, in microseconds: 200 for the lock, 500 between looks for a
  // message (enumerators, not static constants: those would need a definition elsewhere
  // under the C++11 that many robot packages still ask for)
  enum : int { LOCK_POLL_US = 200, MESSAGE_POLL_US = 500 };

  void publishingLoop()
  {
    while (keep_running_)
    {
      lock();
      while (turn_ != NON_REALTIME && keep_running_)
      {
        unlock();
        std::this_thread::sleep_for(std::chrono::microseconds(MESSAGE_POLL_US));
        lock();
      }
      Msg outgoing = msg_;
      turn_ = REALTIME;
      unlock();
      if (keep_running_)
        publisher_.publish(outgoing);
    }
  }

  std::string topic_;
  ros::NodeHandle node_;
  ros::Publisher publisher_;
  std::atomic<bool> keep_running_{false};
  std::atomic<int> turn_{LOOP_NOT_STARTED};
  std::mutex msg_mutex_;
  std::thread thread_;
};

template <class Msg>
using RealtimePublisherSharedPtr = std::shared_ptr<RealtimePublisher<Msg> >;

}  // namespace realtime_tools

#endif  // REALTIME_TOOLS_REALTIME_PUBLISHER_H
