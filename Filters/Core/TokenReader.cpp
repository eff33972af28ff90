// SPDX-License-Identifier: BSD-3-Clause
#include "TokenReader.h"

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <utility>

namespace polycubehex
{

TokenReader::TokenReader(std::string text)
  : Text(std::move(text))
{
}

void TokenReader::SkipSpaceAndComments()
{
  while (this->Position < this->Text.size())
  {
    const char c = this->Text[this->Position];
    if (c == '#')
    {
      while (this->Position < this->Text.size() && this->Text[this->Position] != '\n')
      {
        ++this->Position;
      }
    }
    else if (std::isspace(static_cast<unsigned char>(c)))
    {
      if (c == '\n')
      {
        ++this->CurrentLine;
      }
      ++this->Position;
    }
    else
    {
      return;
    }
  }
}

bool TokenReader::Next(std::string& token)
{
  this->SkipSpaceAndComments();
  if (this->Position >= this->Text.size())
  {
    return false;
  }
  const std::size_t start = this->Position;
  while (this->Position < this->Text.size() &&
    !std::isspace(static_cast<unsigned char>(this->Text[this->Position])) &&
    this->Text[this->Position] != '#')
  {
    ++this->Position;
  }
  token.assign(this->Text, start, this->Position - start);
  this->LastLine = this->CurrentLine;
  return true;
}

bool TokenReader::Peek(std::string& token)
{
  const std::size_t position = this->Position;
  const std::size_t line = this->CurrentLine;
  const std::size_t lastLine = this->LastLine;
  const bool found = this->Next(token);
  this->Position = position;
  this->CurrentLine = line;
  this->LastLine = lastLine;
  return found;
}

bool TokenReader::ParseInteger(const std::string& token, long long& value)
{
  if (token.empty())
  {
    return false;
  }
  errno = 0;
  char* end = nullptr;
  value = std::strtoll(token.c_str(), &end, 10);
  return errno == 0 && end == token.c_str() + token.size();
}

bool TokenReader::ParseDouble(const std::string& token, double& value)
{
  if (token.empty())
  {
    return false;
  }
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  return end == token.c_str() + token.size();
}

bool TokenReader::LooksLikeKeyword(const std::string& token)
{
  return !token.empty() && std::isalpha(static_cast<unsigned char>(token[0]));
}

} // namespace polycubehex
