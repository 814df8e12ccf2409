// gazebo::common::Time: seconds and nanoseconds, as Gazebo 11 declares it.
#ifndef GAZEBO_COMPAT_COMMON_TIME_HH
#define GAZEBO_COMPAT_COMMON_TIME_HH

#include <sys/time.h>
#include <cstdint>
#include <ctime>
#include <iostream>
#include <string>

#include "gazebo/util/system.hh"

namespace gazebo
{
  namespace common
  {
    class GZ_COMMON_VISIBLE Time
    {
      public: static const Time Zero;
      public: static const Time Second;
      public: static const Time Hour;
      public: static const int32_t nsInSec;
      public: static const int32_t nsInMs;

      public: Time();
      public: Time(const Time &_time);
      public: explicit Time(const struct timeval &_tv);
      public: explicit Time(const struct timespec &_tv);
      public: Time(int32_t _sec, int32_t _nsec);
      public: Time(double _time);
      public: virtual ~Time();

      public: static Time Maximum();
      public: static const Time &GetWallTime();
      public: void SetToWallTime();
      public: void Set(int32_t _sec, int32_t _nsec);
      public: void Set(double _seconds);
      public: double Double() const;
      public: float Float() const;
      public: std::string FormattedString(int _start = 0, int _end = 5) const;
      public: static Time Sleep(const common::Time &_time);
      public: static Time MSleep(unsigned int _ms);
      public: static Time NSleep(unsigned int _ns);

      public: Time &operator=(const Time &_time);
      public: Time operator+(const Time &_time) const;
      public: const Time &operator+=(const Time &_time);
      public: Time operator-(const Time &_time) const;
      public: const Time &operator-=(const Time &_time);
      public: Time operator*(const Time &_time) const;
      public: const Time &operator*=(const Time &_time);
      public: Time operator/(const Time &_time) const;
      public: const Time &operator/=(const Time &_time);
      public: bool operator==(const Time &_time) const;
      public: bool operator==(double _time) const;
      public: bool operator!=(const Time &_time) const;
      public: bool operator!=(double _time) const;
      public: bool operator<(const Time &_time) const;
      public: bool operator<(double _time) const;
      public: bool operator<=(const Time &_time) const;
      public: bool operator<=(double _time) const;
      public: bool operator>(const Time &_time) const;
      public: bool operator>(double _time) const;
      public: bool operator>=(const Time &_time) const;
      public: bool operator>=(double _time) const;

      public: friend std::ostream &operator<<(std::ostream &_out, const Time &_t)
      {
        _out << _t.sec << " " << _t.nsec;
        return _out;
      }
      public: friend std::istream &operator>>(std::istream &_in, Time &_t)
      {
        _in >> _t.sec >> _t.nsec;
        _t.Correct();
        return _in;
      }

      public: int32_t sec;
      public: int32_t nsec;

      // keeps 0 <= nsec < 1e9 for positive times (and the signs equal for negative ones)
      private: void Correct();
    };
  }
}
#endif
