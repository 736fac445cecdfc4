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
}

#endif
