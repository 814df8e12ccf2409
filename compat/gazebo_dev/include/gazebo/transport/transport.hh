// gazebo::transport: declared so that gazebo/gazebo.hh compiles; Gazebo's own topics are not
// provided by sim_bridge (plugins talk to ROS instead). Node::Init works; Advertise and
// Subscribe report, by gzerr, that they are not provided and return null pointers.
#ifndef GAZEBO_COMPAT_TRANSPORT_TRANSPORT_HH
#define GAZEBO_COMPAT_TRANSPORT_TRANSPORT_HH
#include <string>
#include <boost/shared_ptr.hpp>

#include "gazebo/common/Console.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
  namespace transport
  {
    class Publisher;
    class Subscriber;
    class Node;
    typedef boost::shared_ptr<Publisher> PublisherPtr;
    typedef boost::shared_ptr<Subscriber> SubscriberPtr;
    typedef boost::shared_ptr<Node> NodePtr;

    class GZ_TRANSPORT_VISIBLE Publisher
    {
      public: bool HasConnections() const { return false; }
      public: void WaitForConnection() const {}
    };

    class GZ_TRANSPORT_VISIBLE Subscriber
    {
      public: std::string GetTopic() const { return this->topic; }
      public: void Unsubscribe() {}
      private: std::string topic;
    };

    class GZ_TRANSPORT_VISIBLE Node
    {
      public: Node() = default;
      public: virtual ~Node() = default;
      public: void Init(const std::string &_space = "") { this->space = _space; }
      public: void Fini() {}
      public: std::string GetTopicNamespace() const { return this->space; }

      public: template<typename M>
              PublisherPtr Advertise(const std::string &_topic, unsigned int = 1000,
                                     double = 0)
      {
        gzerr << "transport::Node::Advertise(" << _topic << ") is not provided by "
              << "sim_bridge (no Gazebo transport); nothing is published" << std::endl;
        return PublisherPtr();
      }

      public: template<typename M, typename T>
              SubscriberPtr Subscribe(const std::string &_topic,
                                      void (T::*)(const boost::shared_ptr<M const> &), T *,
                                      bool = false)
      {
        gzerr << "transport::Node::Subscribe(" << _topic << ") is not provided by "
              << "sim_bridge (no Gazebo transport); nothing will arrive" << std::endl;
        return SubscriberPtr();
      }

      public: template<typename M>
              SubscriberPtr Subscribe(const std::string &_topic,
                                      void (*)(const boost::shared_ptr<M const> &),
                                      bool = false)
      {
        gzerr << "transport::Node::Subscribe(" << _topic << ") is not provided by "
              << "sim_bridge (no Gazebo transport); nothing will arrive" << std::endl;
        return SubscriberPtr();
      }

      private: std::string space;
    };
  }
}
#endif
