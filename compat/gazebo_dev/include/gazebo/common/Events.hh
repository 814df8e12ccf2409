// gazebo::event::Events: the world's events. sim_bridge signals worldUpdateBegin and
// beforePhysicsUpdate before each physics step, worldUpdateEnd after it, worldReset and
// timeReset on a reset, and stop when the simulator closes; the other events can be
// connected to and are never signalled (no GUI, entity or sensor events here).
#ifndef GAZEBO_COMPAT_COMMON_EVENTS_HH
#define GAZEBO_COMPAT_COMMON_EVENTS_HH
#include <string>

#include "gazebo/common/Event.hh"
#include "gazebo/common/UpdateInfo.hh"

namespace gazebo
{
  namespace event
  {
    class GZ_COMMON_VISIBLE Events
    {
      public: template<typename T>
              static ConnectionPtr ConnectWorldUpdateBegin(T _subscriber)
              { return worldUpdateBegin.Connect(_subscriber); }
      public: template<typename T>
              static ConnectionPtr ConnectWorldUpdateEnd(T _subscriber)
              { return worldUpdateEnd.Connect(_subscriber); }
      public: template<typename T>
              static ConnectionPtr ConnectBeforePhysicsUpdate(T _subscriber)
              { return beforePhysicsUpdate.Connect(_subscriber); }
      public: template<typename T>
              static ConnectionPtr ConnectWorldReset(T _subscriber)
              { return worldReset.Connect(_subscriber); }
      public: template<typename T>
              static ConnectionPtr ConnectTimeReset(T _subscriber)
              { return timeReset.Connect(_subscriber); }
      public: template<typename T>
              static ConnectionPtr ConnectStop(T _subscriber)
              { return stop.Connect(_subscriber); }
      public: template<typename T>
              static ConnectionPtr ConnectPause(T _subscriber)
              { return pause.Connect(_subscriber); }
      public: template<typename T>
              static ConnectionPtr ConnectStep(T _subscriber)
              { return step.Connect(_subscriber); }
      public: template<typename T>
              static ConnectionPtr ConnectSigInt(T _subscriber)
              { return sigInt.Connect(_subscriber); }
      public: template<typename T>
              static ConnectionPtr ConnectWorldCreated(T _subscriber)
              { return worldCreated.Connect(_subscriber); }
      public: template<typename T>
              static ConnectionPtr ConnectCreateEntity(T _subscriber)
              { return entityCreated.Connect(_subscriber); }
      public: template<typename T>
              static ConnectionPtr ConnectAddEntity(T _subscriber)
              { return addEntity.Connect(_subscriber); }
      public: template<typename T>
              static ConnectionPtr ConnectDeleteEntity(T _subscriber)
              { return deleteEntity.Connect(_subscriber); }

      public: static EventT<void (const common::UpdateInfo &)> worldUpdateBegin;
      public: static EventT<void ()> worldUpdateEnd;
      public: static EventT<void (const common::UpdateInfo &)> beforePhysicsUpdate;
      public: static EventT<void ()> worldReset;
      public: static EventT<void ()> timeReset;
      public: static EventT<void ()> stop;
      public: static EventT<void (bool)> pause;
      public: static EventT<void ()> step;
      public: static EventT<void ()> sigInt;
      public: static EventT<void (std::string)> worldCreated;
      public: static EventT<void (std::string)> entityCreated;
      public: static EventT<void (std::string)> addEntity;
      public: static EventT<void (std::string)> deleteEntity;
    };
  }
}
#endif
