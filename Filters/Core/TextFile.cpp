// SPDX-License-Identifier: BSD-3-Clause
#include "TextFile.h"

#include <fstream>
#include <sstream>

namespace polycubehex
{
Status ReadTextFile(const std::string& path, std::string& text)
{
  if (path.empty())
  {
    return Status::Failure("no file name was given");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    return Status::Failure("cannot open '" + path + "' for reading");
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad())
  {
    return Status::Failure("reading '" + path + "' failed");
  }
  text = buffer.str();
  return Status::Success();
}
} // namespace polycubehex
