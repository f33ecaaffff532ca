#include "PsiShaderTags.h"

#include <cctype>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace psi
{
namespace
{
bool IsSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\r';
}

std::string Trim(const std::string& s)
{
  size_t b = 0, e = s.size();
  while (b < e && IsSpace(s[b]))
  {
    ++b;
  }
  while (e > b && IsSpace(s[e - 1]))
  {
    --e;
  }
  return s.substr(b, e - b);
}

// The feature of a tag: "//PSI::NearClip::Impl" -> "NearClip".
std::string FeatureOf(const std::string& tag)
{
  return tag.substr(7, tag.find("::", 7) - 7);
}

// The sections of a feature file, in file order: (tag, text). The file's first line is a tag of
// its feature; each tag of that feature starts a section. Tags of other features inside a
// section are kept in its text, to be replaced when their feature is applied.
std::vector<std::pair<std::string, std::string>> Sections(const char* file)
{
  std::vector<std::pair<std::string, std::string>> sections;
  std::string feature;
  for (const std::string& line : Lines(file))
  {
    if (IsTag(line) && (sections.empty() || FeatureOf(Trim(line)) == feature))
    {
      sections.emplace_back(Trim(line), std::string());
      feature = FeatureOf(sections.back().first);
    }
    else if (!sections.empty())
    {
      sections.back().second += line + "\n";
    }
  }
  for (auto& s : sections)
  {
    std::string& t = s.second;
    while (t.size() >= 2 && t[t.size() - 1] == '\n' && t[t.size() - 2] == '\n')
    {
      t.pop_back(); // trailing blank lines separate sections in the file
    }
  }
  return sections;
}
} // namespace

bool IsTag(const std::string& line)
{
  const std::string t = Trim(line);
  if (t.compare(0, 7, "//PSI::") != 0)
  {
    return false;
  }
  const std::string rest = t.substr(7);
  const size_t sep = rest.find("::");
  if (sep == std::string::npos || sep == 0 || sep + 2 >= rest.size())
  {
    return false;
  }
  for (size_t i = 0; i < rest.size(); ++i)
  {
    if (i == sep || i == sep + 1)
    {
      continue;
    }
    if (!std::isalnum(static_cast<unsigned char>(rest[i])))
    {
      return false;
    }
  }
  return true;
}

std::vector<std::string> Lines(const std::string& text)
{
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
  {
    lines.push_back(line);
  }
  return lines;
}

bool ReplaceTag(std::string& src, const std::string& tag, const std::string& with)
{
  for (size_t pos = src.find(tag); pos != std::string::npos; pos = src.find(tag, pos + 1))
  {
    const size_t nl = pos == 0 ? std::string::npos : src.rfind('\n', pos - 1);
    const size_t begin = nl == std::string::npos ? 0 : nl + 1;
    const size_t eol = src.find('\n', pos);
    const size_t end = eol == std::string::npos ? src.size() : eol + 1;
    const size_t lineEnd = eol == std::string::npos ? src.size() : eol;
    if (Trim(src.substr(begin, lineEnd - begin)) == tag)
    {
      src.replace(begin, end - begin, with);
      return true;
    }
  }
  return false;
}

void SubstituteTag(std::string& src, const std::string& tag, const std::string& with)
{
  if (!ReplaceTag(src, tag, with))
  {
    throw std::logic_error("Psi shader composition: no tag " + tag + " to replace");
  }
}

void Apply(std::string& src, const char* file, const std::set<std::string>& skip)
{
  for (const auto& section : Sections(file))
  {
    if (!skip.count(section.first))
    {
      SubstituteTag(src, section.first, section.second);
    }
  }
}

void RemoveTags(std::string& src)
{
  std::string out;
  out.reserve(src.size());
  for (const std::string& line : Lines(src))
  {
    if (!IsTag(line))
    {
      out += line + "\n";
    }
  }
  src.swap(out);
}
} // namespace psi
