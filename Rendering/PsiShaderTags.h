// PsiShaderTags: the one tag substitution of both composers (psi::ComposeShaders and
// psi::ComposeComputeProjector). A tag is a line holding only `//PSI::<Feature>::<Site>`; a
// feature file (Shaders/Psi<Feature><Stage>.glsl) is a list of sections, each starting with the
// tag of the site it replaces. GL-free (plain strings).
#ifndef PsiShaderTags_h
#define PsiShaderTags_h

#include <set>
#include <string>
#include <vector>

namespace psi
{
/// Whether `line` holds only a tag (surrounding blanks allowed).
bool IsTag(const std::string& line);
/// The lines of `text`, without their line breaks.
std::vector<std::string> Lines(const std::string& text);
/// Replaces the line holding only `tag` in `src` by `with` (which ends with a newline, or is
/// empty). False when `src` has no such line.
bool ReplaceTag(std::string& src, const std::string& tag, const std::string& with);
/// ReplaceTag, throwing std::logic_error when `src` has no such line (a template error).
void SubstituteTag(std::string& src, const std::string& tag, const std::string& with);
/// Substitutes the sections of feature file `file` into `src`, except those whose tag is in
/// `skip`; throws std::logic_error when a section finds no tag.
void Apply(std::string& src, const char* file, const std::set<std::string>& skip = {});
/// Removes every tag left (features that are off).
void RemoveTags(std::string& src);
}

#endif
