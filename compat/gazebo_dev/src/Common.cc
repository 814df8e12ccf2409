// gazebo::common: Time, Console, Exception, PID; gazebo::event's events.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <thread>

#include "gazebo/common/Console.hh"
#include "gazebo/common/Events.hh"
#include "gazebo/common/Exception.hh"
#include "gazebo/common/PID.hh"
#include "gazebo/common/Time.hh"

namespace gazebo
{
namespace common
{
// --- Time ---------------------------------------------------------------------------------
const int32_t Time::nsInSec = 1000000000;
const int32_t Time::nsInMs = 1000000;
const Time Time::Zero = common::Time(0, 0);
const Time Time::Second = common::Time(1, 0);
const Time Time::Hour = common::Time(3600, 0);

Time::Time() : sec(0), nsec(0) {}
Time::Time(const Time &_time) : sec(_time.sec), nsec(_time.nsec) {}
Time::Time(const struct timeval &_tv) : sec(_tv.tv_sec), nsec(_tv.tv_usec * 1000) {}
Time::Time(const struct timespec &_tv) : sec(_tv.tv_sec), nsec(_tv.tv_nsec) {}
Time::Time(int32_t _sec, int32_t _nsec) : sec(_sec), nsec(_nsec) { this->Correct(); }
Time::Time(double _time) { this->Set(_time); }
Time::~Time() {}

Time Time::Maximum()
{
  return Time(std::numeric_limits<int32_t>::max(), nsInSec - 1);
}

const Time &Time::GetWallTime()
{
  static thread_local Time wall;
  wall.SetToWallTime();
  return wall;
}

void Time::SetToWallTime()
{
  struct timespec now;
  clock_gettime(CLOCK_REALTIME, &now);
  this->sec = now.tv_sec;
  this->nsec = now.tv_nsec;
}

void Time::Set(int32_t _sec, int32_t _nsec)
{
  this->sec = _sec;
  this->nsec = _nsec;
  this->Correct();
}

void Time::Set(double _seconds)
{
  this->sec = static_cast<int32_t>(std::floor(_seconds));
  this->nsec = static_cast<int32_t>(std::round((_seconds - this->sec) * nsInSec));
  this->Correct();
}

double Time::Double() const
{
  return static_cast<double>(this->sec) + static_cast<double>(this->nsec) * 1e-9;
}

float Time::Float() const { return static_cast<float>(this->Double()); }

std::string Time::FormattedString(int, int) const
{
  std::ostringstream out;
  out << std::fixed << std::setprecision(3) << this->Double();
  return out.str();
}

Time Time::Sleep(const common::Time &_time)
{
  std::this_thread::sleep_for(std::chrono::seconds(_time.sec) +
                              std::chrono::nanoseconds(_time.nsec));
  return Time::Zero;
}

Time Time::MSleep(unsigned int _ms) { return Sleep(Time(0, static_cast<int32_t>(_ms) * nsInMs)); }
Time Time::NSleep(unsigned int _ns) { return Sleep(Time(0, static_cast<int32_t>(_ns))); }

void Time::Correct()
{
  // whole seconds out of nsec, then nsec's sign as sec's
  if (this->nsec >= nsInSec || this->nsec <= -nsInSec)
  {
    this->sec += this->nsec / nsInSec;
    this->nsec = this->nsec % nsInSec;
  }
  if (this->sec > 0 && this->nsec < 0)
  {
    this->sec -= 1;
    this->nsec += nsInSec;
  }
  else if (this->sec < 0 && this->nsec > 0)
  {
    this->sec += 1;
    this->nsec -= nsInSec;
  }
}

Time &Time::operator=(const Time &_time)
{
  this->sec = _time.sec;
  this->nsec = _time.nsec;
  return *this;
}

Time Time::operator+(const Time &_time) const
{
  return Time(this->sec + _time.sec, this->nsec + _time.nsec);
}

const Time &Time::operator+=(const Time &_time)
{
  this->Set(this->sec + _time.sec, this->nsec + _time.nsec);
  return *this;
}

Time Time::operator-(const Time &_time) const
{
  return Time(this->sec - _time.sec, this->nsec - _time.nsec);
}

const Time &Time::operator-=(const Time &_time)
{
  this->Set(this->sec - _time.sec, this->nsec - _time.nsec);
  return *this;
}

Time Time::operator*(const Time &_time) const { return Time(this->Double() * _time.Double()); }
const Time &Time::operator*=(const Time &_time)
{
  this->Set(this->Double() * _time.Double());
  return *this;
}
Time Time::operator/(const Time &_time) const { return Time(this->Double() / _time.Double()); }
const Time &Time::operator/=(const Time &_time)
{
  this->Set(this->Double() / _time.Double());
  return *this;
}

bool Time::operator==(const Time &_time) const
{
  return this->sec == _time.sec && this->nsec == _time.nsec;
}
bool Time::operator==(double _time) const { return *this == Time(_time); }
bool Time::operator!=(const Time &_time) const { return !(*this == _time); }
bool Time::operator!=(double _time) const { return !(*this == _time); }
bool Time::operator<(const Time &_time) const
{
  return this->sec < _time.sec || (this->sec == _time.sec && this->nsec < _time.nsec);
}
bool Time::operator<(double _time) const { return *this < Time(_time); }
bool Time::operator<=(const Time &_time) const { return !(_time < *this); }
bool Time::operator<=(double _time) const { return *this <= Time(_time); }
bool Time::operator>(const Time &_time) const { return _time < *this; }
bool Time::operator>(double _time) const { return *this > Time(_time); }
bool Time::operator>=(const Time &_time) const { return !(*this < _time); }
bool Time::operator>=(double _time) const { return *this >= Time(_time); }

// --- Console ------------------------------------------------------------------------------
namespace
{
bool quiet = true;

// a stream that swallows what is written to it (quiet debug output)
std::ostream &Null()
{
  static std::ostream null(nullptr);
  return null;
}

std::ostream &Prefixed(std::ostream &_stream, const char *_label, const std::string &_file,
                       int _line)
{
  const auto slash = _file.find_last_of('/');
  _stream << _label << " [" << (slash == std::string::npos ? _file : _file.substr(slash + 1))
          << ":" << _line << "] ";
  return _stream;
}
}

std::ostream &Console::Msg()
{
  std::cout << "[Msg] ";
  return std::cout;
}

std::ostream &Console::Dbg(const std::string &_file, int _line)
{
  return quiet ? Null() : Prefixed(std::cout, "[Dbg]", _file, _line);
}

std::ostream &Console::Warn(const std::string &_file, int _line)
{
  return Prefixed(std::cerr, "[Wrn]", _file, _line);
}

std::ostream &Console::Err(const std::string &_file, int _line)
{
  return Prefixed(std::cerr, "[Err]", _file, _line);
}

std::ostream &Console::Log() { return quiet ? Null() : std::cout; }
void Console::SetQuiet(bool _quiet) { quiet = _quiet; }
bool Console::GetQuiet() { return quiet; }

// --- Exception ----------------------------------------------------------------------------
Exception::Exception() : line(0) {}
Exception::Exception(const char *_file, int64_t _line, std::string _msg)
  : file(_file), line(_line), str(std::move(_msg))
{
  gzerr << "EXCEPTION: " << this->str << std::endl;
}
Exception::~Exception() {}
std::string Exception::GetErrorFile() const { return this->file; }
std::string Exception::GetErrorStr() const { return this->str; }
void Exception::Print() const
{
  gazebo::common::Console::Err(this->file, static_cast<int>(this->line))
      << "EXCEPTION: " << this->str << std::endl;
}

InternalError::InternalError() {}
InternalError::InternalError(const char *_file, int64_t _line, const std::string &_msg)
  : Exception(_file, _line, _msg) {}
InternalError::~InternalError() {}

AssertionInternalError::AssertionInternalError(const char *_file, int64_t _line,
                                               const std::string &_expr,
                                               const std::string &_function,
                                               const std::string &_msg)
  : InternalError(_file, _line, "GZ_ASSERT( " + _expr + " ) failed in " + _function +
                  (_msg.empty() ? std::string() : ": " + _msg)) {}
AssertionInternalError::~AssertionInternalError() {}

// --- PID ----------------------------------------------------------------------------------
PID::PID(double _p, double _i, double _d, double _imax, double _imin, double _cmdMax,
         double _cmdMin)
{
  this->Init(_p, _i, _d, _imax, _imin, _cmdMax, _cmdMin);
}

PID::~PID() {}

void PID::Init(double _p, double _i, double _d, double _imax, double _imin, double _cmdMax,
               double _cmdMin)
{
  this->pGain = _p;
  this->iGain = _i;
  this->dGain = _d;
  this->iMax = _imax;
  this->iMin = _imin;
  this->cmdMax = _cmdMax;
  this->cmdMin = _cmdMin;
  this->Reset();
}

void PID::SetPGain(double _p) { this->pGain = _p; }
void PID::SetIGain(double _i) { this->iGain = _i; }
void PID::SetDGain(double _d) { this->dGain = _d; }
void PID::SetIMax(double _i) { this->iMax = _i; }
void PID::SetIMin(double _i) { this->iMin = _i; }
void PID::SetCmdMax(double _c) { this->cmdMax = _c; }
void PID::SetCmdMin(double _c) { this->cmdMin = _c; }
double PID::GetPGain() const { return this->pGain; }
double PID::GetIGain() const { return this->iGain; }
double PID::GetDGain() const { return this->dGain; }
double PID::GetIMax() const { return this->iMax; }
double PID::GetIMin() const { return this->iMin; }
double PID::GetCmdMax() const { return this->cmdMax; }
double PID::GetCmdMin() const { return this->cmdMin; }

double PID::Update(double _error, common::Time _dt)
{
  const double dt = _dt.Double();
  if (dt == 0.0 || std::isnan(_error) || std::isinf(_error))
    return 0.0;
  this->pErr = _error;
  const double pTerm = this->pGain * this->pErr;
  this->iErr += dt * this->pErr;
  double iTerm = this->iGain * this->iErr;
  // the integral held within [iMin, iMax], the error kept consistent with it
  if (iTerm > this->iMax)
  {
    iTerm = this->iMax;
    if (std::fabs(this->iGain) >= 1e-10)
      this->iErr = iTerm / this->iGain;
  }
  else if (iTerm < this->iMin)
  {
    iTerm = this->iMin;
    if (std::fabs(this->iGain) >= 1e-10)
      this->iErr = iTerm / this->iGain;
  }
  if (dt != 0.0)
    this->dErr = (this->pErr - this->pErrLast) / dt;
  this->pErrLast = this->pErr;
  const double dTerm = this->dGain * this->dErr;
  this->cmd = -pTerm - iTerm - dTerm;
  if (this->cmdMax >= this->cmdMin)
  {
    if (this->cmd > this->cmdMax)
      this->cmd = this->cmdMax;
    if (this->cmd < this->cmdMin)
      this->cmd = this->cmdMin;
  }
  return this->cmd;
}

void PID::SetCmd(double _cmd) { this->cmd = _cmd; }
double PID::GetCmd() { return this->cmd; }

void PID::GetErrors(double &_pe, double &_ie, double &_de)
{
  _pe = this->pErr;
  _ie = this->iErr;
  _de = this->dErr;
}

PID &PID::operator=(const PID &_p)
{
  if (this == &_p)
    return *this;
  this->pGain = _p.pGain;
  this->iGain = _p.iGain;
  this->dGain = _p.dGain;
  this->iMax = _p.iMax;
  this->iMin = _p.iMin;
  this->cmdMax = _p.cmdMax;
  this->cmdMin = _p.cmdMin;
  this->pErrLast = _p.pErrLast;
  this->pErr = _p.pErr;
  this->iErr = _p.iErr;
  this->dErr = _p.dErr;
  this->cmd = _p.cmd;
  return *this;
}

void PID::Reset()
{
  this->pErrLast = 0.0;
  this->pErr = 0.0;
  this->iErr = 0.0;
  this->dErr = 0.0;
  this->cmd = 0.0;
}
}  // namespace common

namespace event
{
Event::Event() : signaled(false) {}
Event::~Event() {}
bool Event::Signaled() const { return this->signaled; }
void Event::SetSignaled(const bool _sig) { this->signaled = _sig; }

Connection::Connection(Event *_e, const int _i) : event(_e), id(_i) {}
Connection::~Connection()
{
  if (this->event)
    this->event->Disconnect(this->id);
}
int Connection::Id() const { return this->id; }

EventT<void (const common::UpdateInfo &)> Events::worldUpdateBegin;
EventT<void ()> Events::worldUpdateEnd;
EventT<void (const common::UpdateInfo &)> Events::beforePhysicsUpdate;
EventT<void ()> Events::worldReset;
EventT<void ()> Events::timeReset;
EventT<void ()> Events::stop;
EventT<void (bool)> Events::pause;
EventT<void ()> Events::step;
EventT<void ()> Events::sigInt;
EventT<void (std::string)> Events::worldCreated;
EventT<void (std::string)> Events::entityCreated;
EventT<void (std::string)> Events::addEntity;
EventT<void (std::string)> Events::deleteEntity;
}  // namespace event
}  // namespace gazebo
