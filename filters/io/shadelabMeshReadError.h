/**
 * @class   shadelab::MeshReadError
 * @brief   the one-line error that stops a mesh parser
 *
 * Parsing stops at the first problem. vtkShadelabFileReader::RequestData
 * catches this, reports it through vtkErrorMacro and returns 0, so that no
 * partial mesh ever leaves a reader. The code is a vtkErrorCode value for the
 * reader's ErrorCode.
 */
#ifndef shadelabMeshReadError_h
#define shadelabMeshReadError_h

#include <vtkErrorCode.h>

#include <new>
#include <stdexcept>
#include <string>

namespace shadelab
{
class MeshReadError : public std::runtime_error
{
public:
  explicit MeshReadError(
    const std::string& message, unsigned long code = vtkErrorCode::FileFormatError)
    : std::runtime_error(message)
    , Code(code)
  {
  }
  unsigned long GetCode() const { return this->Code; }

private:
  unsigned long Code;
};

/**
 * The exception being handled, as a reader reports it: a MeshReadError as
 * it is, std::bad_alloc as "out of memory", any other std::exception (a
 * library's: the JSON parser's) as its what(); both with UnknownError. Only
 * inside a handler of std::exception.
 */
inline MeshReadError CurrentReadError()
{
  try
  {
    throw;
  }
  catch (const MeshReadError& error)
  {
    return error;
  }
  catch (const std::bad_alloc&)
  {
    return MeshReadError("out of memory", vtkErrorCode::UnknownError);
  }
  catch (const std::exception& error)
  {
    return MeshReadError(error.what(), vtkErrorCode::UnknownError);
  }
}
}

#endif
