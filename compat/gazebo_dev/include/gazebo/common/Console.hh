// gzmsg, gzdbg, gzwarn, gzerr and gzlog: streams with Gazebo's "[Err] [file:line] " prefixes.
// gzmsg goes to stdout, the others to stderr; gzdbg and gzlog print only when
// Console::SetQuiet(false) was called (Gazebo prints debug output with --verbose only).
#ifndef GAZEBO_COMPAT_COMMON_CONSOLE_HH
#define GAZEBO_COMPAT_COMMON_CONSOLE_HH
#include <ostream>
#include <string>
#include "gazebo/util/system.hh"

namespace gazebo
{
  namespace common
  {
    class GZ_COMMON_VISIBLE Console
    {
      public: static std::ostream &Msg();
      public: static std::ostream &Dbg(const std::string &_file, int _line);
      public: static std::ostream &Warn(const std::string &_file, int _line);
      public: static std::ostream &Err(const std::string &_file, int _line);
      public: static std::ostream &Log();
      public: static void SetQuiet(bool _quiet);
      public: static bool GetQuiet();
    };
  }
}

#define gzmsg (gazebo::common::Console::Msg())
#define gzdbg (gazebo::common::Console::Dbg(__FILE__, __LINE__))
#define gzwarn (gazebo::common::Console::Warn(__FILE__, __LINE__))
#define gzerr (gazebo::common::Console::Err(__FILE__, __LINE__))
#define gzlog (gazebo::common::Console::Log())
#endif
