// PsiOFFTokenizer: the lexical layer of the tetrahedral OFF format (see PsiOFFParser.h): content
// lines of a byte buffer, whitespace-separated tokens and strict number parsing. Plain C++ (no
// VTK), testable alone.
#ifndef PsiOFFTokenizer_h
#define PsiOFFTokenizer_h

#include <cstddef>
#include <cstdint>
#include <string>

namespace psi
{
namespace off
{
/// A token: the bytes [Begin, End) of a line.
struct Token
{
  const char* Begin;
  const char* End;
  /// The token for a message: at most 40 bytes, non-printable bytes escaped as \xNN, "..." when
  /// cut.
  std::string Text() const;
};

/// Lines of a byte buffer, numbered from 1; blank lines and '#' comment lines are skipped. A
/// leading UTF-8 byte-order mark is not part of the content.
class LineCursor
{
public:
  LineCursor(const char* data, size_t size);

  /// The next line with content, without its '\n'; false at the end of the buffer.
  bool NextContentLine(const char*& begin, const char*& end);

  /// Bytes after the last line returned.
  size_t Remaining() const { return static_cast<size_t>(this->End - this->P); }

  /// The number of the last line read (content or not).
  uint64_t Line = 0;

private:
  const char* P;
  const char* End;
};

/// Splits [begin, end) at whitespace (space, \t, \r, \v, \f) into at most maxTokens tokens;
/// returns the number of tokens found, which is maxTokens + 1 when there are more.
int Tokenize(const char* begin, const char* end, Token* tokens, int maxTokens);

enum class NumberStatus
{
  Ok,
  NotANumber,
  OutOfRange
};

/// The whole token as a double (std::from_chars' general format, plus an optional leading '+').
NumberStatus ParseDouble(const Token& t, double& value);

/// The whole token as a non-negative decimal integer (an optional leading '+' is accepted).
NumberStatus ParseCount(const Token& t, uint64_t& value);

/// Whether the token is "OFF", in any case.
bool IsOFFKeyword(const Token& t);
} // namespace off
} // namespace psi

#endif
