// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <string>

namespace polycubehex
{

/// Reads whitespace-separated tokens from a text held in memory, skipping `#` comments to the
/// end of the line. Shared by the MEDIT and OFF parsers, whose layouts are free across lines.
class TokenReader
{
public:
  explicit TokenReader(std::string text);

  /// Next token; false at the end of the text.
  bool Next(std::string& token);
  /// Next token without consuming it; false at the end of the text.
  bool Peek(std::string& token);
  /// Bytes not yet read: an upper bound on how many more numbers the text can hold (x2).
  std::size_t RemainingBytes() const { return this->Text.size() - this->Position; }
  /// 1-based line number of the last token read, for error messages.
  std::size_t Line() const { return this->LastLine; }

  /// Token parsing that accepts the whole token only ("1x" is not an integer).
  static bool ParseInteger(const std::string& token, long long& value);
  static bool ParseDouble(const std::string& token, double& value);
  /// True when the token starts like a keyword (a letter), not like a number.
  static bool LooksLikeKeyword(const std::string& token);

private:
  void SkipSpaceAndComments();

  std::string Text;
  std::size_t Position = 0;
  std::size_t CurrentLine = 1;
  std::size_t LastLine = 1;
};

} // namespace polycubehex
