// gazebo::event::Event, EventT and Connection. A connection lasts as long as its
// ConnectionPtr: dropping (or reset()-ing) it disconnects the subscriber, as in Gazebo 11,
// which has no Disconnect* functions any more. Connecting, disconnecting and signalling are
// thread-safe; a subscriber may drop its own connection while it is being called.
#ifndef GAZEBO_COMPAT_COMMON_EVENT_HH
#define GAZEBO_COMPAT_COMMON_EVENT_HH
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include "gazebo/common/CommonTypes.hh"
#include "gazebo/common/Console.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
  namespace event
  {
    class GZ_COMMON_VISIBLE Event
    {
      public: Event();
      public: virtual ~Event();
      public: virtual void Disconnect(int _id) = 0;
      public: bool Signaled() const;
      public: void SetSignaled(const bool _sig);
      private: bool signaled;
    };

    class GZ_COMMON_VISIBLE Connection
    {
      public: Connection(Event *_e, const int _i);
      public: ~Connection();
      public: int Id() const;
      private: Event *event;
      private: int id;
    };

    template<typename T>
    class EventT : public Event
    {
      public: EventT() = default;
      public: virtual ~EventT() = default;

      public: ConnectionPtr Connect(const std::function<T> &_subscriber)
      {
        std::lock_guard<std::recursive_mutex> lock(this->mutex);
        const int id = this->nextId++;
        this->subscribers[id] = std::make_shared<std::function<T>>(_subscriber);
        return ConnectionPtr(new Connection(this, id));
      }

      public: virtual void Disconnect(int _id) override
      {
        std::lock_guard<std::recursive_mutex> lock(this->mutex);
        this->subscribers.erase(_id);
      }

      public: unsigned int ConnectionCount() const
      {
        std::lock_guard<std::recursive_mutex> lock(this->mutex);
        return static_cast<unsigned int>(this->subscribers.size());
      }

      public: template<typename... Args> void operator()(Args &&... _args)
      {
        this->Signal(std::forward<Args>(_args)...);
      }

      // Calls each subscriber still connected when its turn comes; an exception one throws
      // is reported (gzerr) and the others still run, as the simulation must go on.
      public: template<typename... Args> void Signal(Args &&... _args)
      {
        std::vector<std::pair<int, std::shared_ptr<std::function<T>>>> calls;
        {
          std::lock_guard<std::recursive_mutex> lock(this->mutex);
          this->SetSignaled(true);
          calls.assign(this->subscribers.begin(), this->subscribers.end());
        }
        for (auto &call : calls)
        {
          {
            std::lock_guard<std::recursive_mutex> lock(this->mutex);
            if (this->subscribers.find(call.first) == this->subscribers.end())
              continue;
          }
          try
          {
            (*call.second)(_args...);
          }
          catch (const std::exception &_e)
          {
            gzerr << "an event subscriber threw: " << _e.what() << std::endl;
          }
        }
      }

      private: mutable std::recursive_mutex mutex;
      private: std::map<int, std::shared_ptr<std::function<T>>> subscribers;
      private: int nextId = 0;
    };
  }
}
#endif
