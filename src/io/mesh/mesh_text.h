#pragma once
// Whitespace-separated tokens with their line numbers, for the text mesh formats (Gmsh, TetGen,
// legacy VTK), and the one-line errors they raise: "FILE:LINE: expected X, got 'Y'".
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>

#include "pbd/core/types.h"

namespace hs::io {

class MeshTokens {
 public:
  // `commentChar`: from it to the end of the line is skipped ('\0' for none).
  // `firstLine`: the line number of the text's start (a part of a larger file).
  MeshTokens(std::string_view text, std::string name, char commentChar = '\0', long firstLine = 1)
      : m_text(text), m_name(std::move(name)), m_comment(commentChar), m_line(firstLine), m_tokenLine(firstLine) {}

  // The next token; throws "FILE:LINE: expected <what>, got end of file" at the end.
  std::string_view next(std::string_view what);
  // The next token without consuming it; empty at the end of the text.
  std::string_view peek();
  bool atEnd() { return peek().empty(); }
  // The rest of the current line (after the last token read), trimmed; moves to the next line.
  std::string_view restOfLine();

  double real(std::string_view what);           // finite decimal number
  pbd::Vec3 point(std::string_view what);       // three reals, finite in pbd::Real too
  long long integer(std::string_view what);     // decimal integer
  long long count(std::string_view what, long long limit);  // integer in [0, limit]
  void expect(std::string_view keyword);        // exactly this token

  long line() const { return m_tokenLine; }     // line of the last token read (1-based)
  const std::string& name() const { return m_name; }
  // "FILE:LINE: message", one line (control characters of quoted input shown as '?').
  [[noreturn]] void fail(const std::string& message) const;

 private:
  void skipSpace();
  std::string_view m_text;
  std::string m_name;
  char m_comment;
  std::size_t m_pos = 0;
  long m_line;
  long m_tokenLine;
};

// At most 40 characters of `s`, control characters replaced: safe to quote in a one-line error.
std::string excerpt(std::string_view s);

// The upper bound on counts read from a file's header: more elements than bytes left cannot be
// in the file, and a forged count must not reserve gigabytes before failing.
inline long long countLimit(std::string_view text) { return static_cast<long long>(text.size()); }

}  // namespace hs::io
