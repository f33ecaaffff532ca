#include "PsiOFFTokenizer.h"

#include <algorithm>
#include <charconv>
#include <cstring>
#include <system_error>

namespace
{
inline bool IsSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}
} // namespace

namespace psi
{
namespace off
{
std::string Token::Text() const
{
  static const char* const hex = "0123456789abcdef";
  std::string out;
  const size_t n = std::min<size_t>(static_cast<size_t>(End - Begin), 40);
  for (size_t i = 0; i < n; ++i)
  {
    const unsigned char c = static_cast<unsigned char>(Begin[i]);
    if (c >= 0x20 && c < 0x7f)
    {
      out += static_cast<char>(c);
    }
    else
    {
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  if (static_cast<size_t>(End - Begin) > n)
  {
    out += "...";
  }
  return out;
}

LineCursor::LineCursor(const char* data, size_t size)
  : P(data)
  , End(data + size)
{
  if (size >= 3 && std::memcmp(data, "\xEF\xBB\xBF", 3) == 0)
  {
    this->P += 3;
  }
}

bool LineCursor::NextContentLine(const char*& begin, const char*& end)
{
  while (this->P < this->End)
  {
    const char* nl = static_cast<const char*>(std::memchr(this->P, '\n', this->End - this->P));
    begin = this->P;
    end = nl ? nl : this->End;
    this->P = nl ? nl + 1 : this->End;
    ++this->Line;
    const char* q = begin;
    while (q < end && IsSpace(*q))
    {
      ++q;
    }
    if (q == end || *q == '#')
    {
      continue;
    }
    return true;
  }
  return false;
}

int Tokenize(const char* begin, const char* end, Token* tokens, int maxTokens)
{
  int n = 0;
  const char* p = begin;
  while (true)
  {
    while (p < end && IsSpace(*p))
    {
      ++p;
    }
    if (p == end)
    {
      return n;
    }
    if (n == maxTokens)
    {
      return n + 1;
    }
    const char* s = p;
    while (p < end && !IsSpace(*p))
    {
      ++p;
    }
    tokens[n++] = Token{ s, p };
  }
}

NumberStatus ParseDouble(const Token& t, double& value)
{
  const char* b = t.Begin;
  if (b < t.End && *b == '+')
  {
    ++b; // from_chars does not take a leading '+'
    if (b < t.End && (*b == '-' || *b == '+'))
    {
      return NumberStatus::NotANumber;
    }
  }
  const auto r = std::from_chars(b, t.End, value, std::chars_format::general);
  if (r.ec == std::errc::result_out_of_range && r.ptr == t.End)
  {
    return NumberStatus::OutOfRange;
  }
  if (r.ec != std::errc() || r.ptr != t.End)
  {
    return NumberStatus::NotANumber;
  }
  return NumberStatus::Ok;
}

NumberStatus ParseCount(const Token& t, uint64_t& value)
{
  const char* b = t.Begin;
  if (b < t.End && *b == '+')
  {
    ++b;
  }
  if (b == t.End || *b < '0' || *b > '9')
  {
    return NumberStatus::NotANumber;
  }
  const auto r = std::from_chars(b, t.End, value, 10);
  if (r.ec == std::errc::result_out_of_range)
  {
    return NumberStatus::OutOfRange;
  }
  if (r.ec != std::errc() || r.ptr != t.End)
  {
    return NumberStatus::NotANumber;
  }
  return NumberStatus::Ok;
}

bool IsOFFKeyword(const Token& t)
{
  return t.End - t.Begin == 3 && (t.Begin[0] == 'O' || t.Begin[0] == 'o') &&
    (t.Begin[1] == 'F' || t.Begin[1] == 'f') && (t.Begin[2] == 'F' || t.Begin[2] == 'f');
}
} // namespace off
} // namespace psi
