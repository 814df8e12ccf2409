// gazebo::common::PID with Gazebo 11's semantics: Update takes the error as measured minus
// target and returns -(p + i + d); the integral term is clamped to [iMin, iMax], which are 0
// by default (so no integral action unless they are set); the command is clamped to
// [cmdMin, cmdMax] only when cmdMax >= cmdMin (by default it is not clamped).
#ifndef GAZEBO_COMPAT_COMMON_PID_HH
#define GAZEBO_COMPAT_COMMON_PID_HH
#include "gazebo/common/Time.hh"

namespace gazebo
{
  namespace common
  {
    class GZ_COMMON_VISIBLE PID
    {
      public: PID(double _p = 0.0, double _i = 0.0, double _d = 0.0,
                  double _imax = 0.0, double _imin = 0.0,
                  double _cmdMax = -1.0, double _cmdMin = 0.0);
      public: virtual ~PID();
      public: void Init(double _p = 0.0, double _i = 0.0, double _d = 0.0,
                        double _imax = 0.0, double _imin = 0.0,
                        double _cmdMax = -1.0, double _cmdMin = 0.0);
      public: void SetPGain(double _p);
      public: void SetIGain(double _i);
      public: void SetDGain(double _d);
      public: void SetIMax(double _i);
      public: void SetIMin(double _i);
      public: void SetCmdMax(double _c);
      public: void SetCmdMin(double _c);
      public: double GetPGain() const;
      public: double GetIGain() const;
      public: double GetDGain() const;
      public: double GetIMax() const;
      public: double GetIMin() const;
      public: double GetCmdMax() const;
      public: double GetCmdMin() const;
      public: double Update(double _error, common::Time _dt);
      public: void SetCmd(double _cmd);
      public: double GetCmd();
      public: void GetErrors(double &_pe, double &_ie, double &_de);
      public: PID &operator=(const PID &_p);
      public: void Reset();

      private: double pErrLast = 0.0;
      private: double pErr = 0.0;
      private: double iErr = 0.0;
      private: double dErr = 0.0;
      private: double pGain = 0.0;
      private: double iGain = 0.0;
      private: double dGain = 0.0;
      private: double iMax = 0.0;
      private: double iMin = 0.0;
      private: double cmdMax = -1.0;
      private: double cmdMin = 0.0;
      private: double cmd = 0.0;
    };
  }
}
#endif
