// gazebo::common::Exception and gzthrow, which plugins throw from Load.
#ifndef GAZEBO_COMPAT_COMMON_EXCEPTION_HH
#define GAZEBO_COMPAT_COMMON_EXCEPTION_HH
#include <iostream>
#include <sstream>
#include <string>
#include "gazebo/util/system.hh"

namespace gazebo
{
  namespace common
  {
    class GZ_COMMON_VISIBLE Exception
    {
      public: Exception();
      public: Exception(const char *_file, int64_t _line, std::string _msg);
      public: virtual ~Exception();
      public: std::string GetErrorFile() const;
      public: std::string GetErrorStr() const;
      public: void Print() const;
      public: friend std::ostream &operator<<(std::ostream &_out,
                                              const gazebo::common::Exception &_err)
      {
        return _out << _err.GetErrorStr();
      }
      private: std::string file;
      private: int64_t line;
      private: std::string str;
    };

    class GZ_COMMON_VISIBLE InternalError : public Exception
    {
      public: InternalError();
      public: InternalError(const char *_file, int64_t _line, const std::string &_msg);
      public: virtual ~InternalError();
    };

    class GZ_COMMON_VISIBLE AssertionInternalError : public InternalError
    {
      public: AssertionInternalError(const char *_file, int64_t _line,
                                     const std::string &_expr, const std::string &_function,
                                     const std::string &_msg = "");
      public: virtual ~AssertionInternalError();
    };
  }
}

#define gzthrow(msg) \
  { \
    std::ostringstream throwStream; \
    throwStream << msg << std::endl << std::flush; \
    throw gazebo::common::Exception(__FILE__, __LINE__, throwStream.str()); \
  }
#endif
