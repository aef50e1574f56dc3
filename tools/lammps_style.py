#!/usr/bin/env python3
# ----------------------------------------------------------------------
# NSCD package for LAMMPS: Non-Smooth Contact Dynamics of rigid
# spheropolyhedra coupled to elastic wires.
#
# Copyright (2026) the NSCD package developers. This software is
# distributed under the GNU General Public License, version 2, the
# licence of LAMMPS. See the LICENSE file in the top-level directory
# of the package.
# ----------------------------------------------------------------------
# Contributing author: the NSCD package developers
# ----------------------------------------------------------------------

"""Four of LAMMPS' style rules (doc/src/Modify_style.rst, Modify_requirements.rst of the
LAMMPS tree) checked on the package's src/ (doc/build.md, "LAMMPS' style rules"):

1. no member initialiser (`int n = 0;`, `Tally t{};`) in a class of a src/ header: members
   are set in the constructor. Headers of plain helper structs that only our .cpp files
   include are left out (HELPER_HEADERS below, each with its reason), never one that LAMMPS'
   core compiles: a style header (a `...Style(` macro), a src/ header it includes, or one
   with a class derived from a LAMMPS class (Fix, Compute, Pointers, ...);
2. no `kName` constant in src/: LAMMPS names constants in UPPERCASE. A `kName` of lib/
   (lib/ is not LAMMPS code and keeps its style) may be used there, unless src/ declares
   one of the same name;
3. no error or warning message (the format string of error->all, error->one,
   error->warning) longer than MAX_MESSAGE characters: at most two lines as LAMMPS prints
   them (`ERROR: ` + the message + ` (src/NSCD/file.cpp:123)`, 80 columns a line, with room
   for the values the placeholders take). Longer explanations go to the style's page in doc/,
   under its section 'Errors'; a message naming a page ("doc/fix_wire.rst, Errors") must name
   one that exists, with that heading (a section title of the reStructuredText page, or a '## '
   heading of a Markdown page);
4. the package's helpers in one namespace, LAMMPS_NS::NSCD_NS (PACKAGE_NAMESPACE), as LAMMPS'
   packages keep theirs (GRANULAR's Granular_NS, RHEO's RHEO_NS): directly in LAMMPS_NS only
   the styles and the classes derived from a LAMMPS class (their bases), forward declarations
   and the definitions of their nested classes; no other namespace inside LAMMPS_NS and no
   other top-level namespace than LAMMPS_NS, lib/'s `nscd` (forward declarations only) and
   unnamed ones; no function with external linkage at global scope other than members.

Prints every breach as file:line and exits 1 if there is one.

    lammps_style.py REPO_DIR [--lengths]     (--lengths: every message's length, longest first)
"""
import pathlib
import re
import sys

MAX_MESSAGE = 120
PACKAGE_NAMESPACE = "NSCD_NS"
LIB_NAMESPACE = "nscd"    # lib/'s top-level namespace: src/ may forward-declare its types

# src/ headers of plain helper structs that only the package's .cpp files include (never a
# style header, so LAMMPS' core does not compile them): records kept as aggregates with their
# defaults beside the fields, as LAMMPS' own helper classes do (math_eigen_impl.h).
HELPER_HEADERS = {
    "fix_wire_lib.h": "fix wire's private state behind its pointer (the pimpl struct)",
    "nscd_contact.h": "the contact law's two numbers, a plain struct",
    "nscd_contact_pairs.h": "a contact pair's sums, a plain struct",
    "nscd_restart_blocks.h": "restart blocks as read, plain structs",
}

LAMMPS_BASES = r"(Pointers|Fix|Compute|Pair|Bond|Angle|Dump|Command|AtomVec)"


def strip_comments_and_strings(text, keep_strings=False):
    """The text with comments (and string and character literals, unless keep_strings) blanked,
    newlines kept so that offsets give the same line numbers."""
    pattern = re.compile(r'//[^\n]*|/\*.*?\*/|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'', re.S)

    def blank(m):
        s = m.group(0)
        if keep_strings and s[0] in "\"'":
            return s
        return re.sub(r"[^\n]", " ", s)

    return pattern.sub(blank, text)


def line_of(text, offset):
    return text.count("\n", 0, offset) + 1


# ---------------------------------------------------------------- member initialisers

def top_level_equals(statement):
    """Offset of the first '=' outside (), <>, [] that is not part of ==, <=, >=, !=; -1 if none."""
    depth = 0
    for i, ch in enumerate(statement):
        if ch in "([<":
            depth += 1
        elif ch in ")]>":
            depth -= 1
        elif ch == "=" and depth == 0:
            before = statement[i - 1] if i else ""
            after = statement[i + 1] if i + 1 < len(statement) else ""
            if after != "=" and before not in "=<>!":
                return i
    return -1


def is_member_initialiser(statement):
    """Whether a declaration in a class body (up to its ';') initialises a data member."""
    s = re.sub(r"\boperator\s*[^\s(]+\s*\(", "operator(", statement).strip()
    s = re.sub(r"^(public|protected|private)\s*:", "", s).strip()
    if not s or re.match(r"(using|typedef|friend|static_assert|template)\b", s):
        return False
    if re.match(r"(static\s+)?(inline\s+)?(constexpr|static\s+const)\b", s) or re.match(r"static\s+constexpr\b", s):
        return False    # a class constant: initialised where it is declared, as C++ asks
    eq = top_level_equals(s)
    if eq < 0:
        return False
    if "(" in s[:eq]:
        return False    # a function: default arguments, = default, = delete, = 0
    return True


def member_initialisers(text):
    """(offset, statement) of each member initialiser in the classes of `text` (comments and
    strings already blanked)."""
    found = []
    stack = []          # one entry per open '{': 'class', 'enum', 'namespace', 'other'
    start = 0           # where the current statement began
    i = 0
    while i < len(text):
        ch = text[i]
        if ch == "{":
            head = text[start:i]
            in_class = bool(stack) and stack[-1] == "class"
            if re.search(r"\benum\b", head):
                kind = "enum"
            elif re.search(r"\b(class|struct|union)\b", head) and "(" not in head and "=" not in head:
                kind = "class"
            elif re.search(r"\bnamespace\b", head) or re.search(r'extern\s+"C"', head):
                kind = "namespace"
            else:
                kind = "other"
                if in_class and "(" not in head and head.strip() and not head.strip().endswith(")"):
                    # `Type name{value};` in a class: a brace member initialiser
                    found.append((start + len(head) - len(head.lstrip()), head.strip() + "{...}"))
            stack.append(kind)
            start = i + 1
        elif ch == "}":
            if stack:
                stack.pop()
            start = i + 1
        elif ch == ";":
            if stack and stack[-1] == "class":
                statement = text[start:i]
                if is_member_initialiser(statement):
                    found.append((start + len(statement) - len(statement.lstrip()), statement.strip()))
            start = i + 1
        elif ch == ":" and stack and stack[-1] == "class":
            word = text[start:i].strip()
            if word in ("public", "protected", "private"):
                start = i + 1
        i += 1
    return found


def core_compiled_headers(src):
    """The src/ headers LAMMPS' core compiles (style headers and what they include from src/)
    and the headers of classes derived from LAMMPS classes."""
    headers = {p.name: p for p in src.glob("*.h")}
    chosen = set()
    todo = [name for name, p in headers.items() if re.search(r"^\s*\w+Style\(", p.read_text(), re.M)]
    todo += [name for name, p in headers.items()
             if re.search(r"\bclass\s+\w+\s*(final\s*)?:\s*(public|protected)\s+" + LAMMPS_BASES + r"\b",
                          p.read_text())]
    while todo:
        name = todo.pop()
        if name in chosen:
            continue
        chosen.add(name)
        for inc in re.findall(r'^\s*#\s*include\s+"([^"]+)"', headers[name].read_text(), re.M):
            if inc in headers:
                todo.append(inc)
    return sorted(chosen)


def check_member_initialisers(src):
    problems = []
    core = core_compiled_headers(src)
    for name in sorted(p.name for p in src.glob("*.h")):
        if name in HELPER_HEADERS:
            if name in core:
                problems.append(f"src/{name}: listed as a helper header, but LAMMPS' core compiles it")
            continue
        text = strip_comments_and_strings((src / name).read_text())
        for offset, statement in member_initialisers(text):
            statement = " ".join(statement.split())
            problems.append(f"src/{name}:{line_of(text, offset)}: member initialiser in a header "
                            f"(set it in the constructor): {statement}")
    return problems


# ---------------------------------------------------------------- kName constants

K_NAME = re.compile(r"\bk[A-Z]\w*")


def lib_k_names(lib):
    names = set()
    for path in lib.rglob("*"):
        if path.suffix in (".h", ".hpp", ".cpp"):
            names.update(K_NAME.findall(strip_comments_and_strings(path.read_text())))
    return names


K_DECLARED = re.compile(r"\b(k[A-Z]\w*)\s*(=(?!=)|\{)")


def check_k_constants(src, lib):
    texts = {path: strip_comments_and_strings(path.read_text())
             for path in sorted(src.rglob("*")) if path.suffix in (".h", ".cpp")}
    declared_here = {m.group(1) for text in texts.values() for m in K_DECLARED.finditer(text)}
    allowed = lib_k_names(lib) - declared_here
    problems = []
    for path, text in texts.items():
        for m in K_NAME.finditer(text):
            if m.group(0) not in allowed:
                problems.append(f"{path.relative_to(src.parent)}:{line_of(text, m.start())}: constant "
                                f"{m.group(0)}: LAMMPS names constants in UPPERCASE")
    return problems


# ---------------------------------------------------------------- message lengths

CALL = re.compile(r"\berror->(all|one|warning)\s*\(")
LITERAL = re.compile(r'"((?:\\.|[^"\\\n])*)"')


def call_arguments(text, open_paren):
    """The text between the '(' at open_paren and its matching ')'."""
    depth = 0
    i = open_paren
    while i < len(text):
        ch = text[i]
        if ch == '"':
            i = LITERAL.match(text, i).end()
            continue
        if ch == "(":
            depth += 1
        elif ch == ")":
            depth -= 1
            if depth == 0:
                return text[open_paren + 1:i]
        i += 1
    return text[open_paren + 1:]


def messages(path):
    """(line, kind, message) of each error->all/one/warning call of the file: its first string
    argument, adjacent literals joined (the format string as written)."""
    raw = path.read_text()
    text = strip_comments_and_strings(raw, keep_strings=True)
    found = []
    for m in CALL.finditer(text):
        args = call_arguments(text, m.end() - 1)
        first = re.match(r'\s*FLERR\s*,\s*((?:"(?:\\.|[^"\\\n])*"\s*)+)', args)
        if not first:
            continue
        message = "".join(LITERAL.findall(first.group(1)))
        found.append((line_of(text, m.start()), m.group(1), bytes(message, "utf-8").decode("unicode_escape")))
    return found


def check_messages(src, show_lengths=False):
    problems = []
    table = []
    for path in sorted(src.rglob("*")):
        if path.suffix not in (".h", ".cpp"):
            continue
        for line, kind, message in messages(path):
            where = f"{path.relative_to(src.parent)}:{line}"
            table.append((len(message), where, message))
            if len(message) > MAX_MESSAGE:
                problems.append(f"{where}: {kind} message of {len(message)} characters (at most {MAX_MESSAGE}; "
                                f"the explanation goes to the style's doc page): {message}")
    if show_lengths:
        for length, where, message in sorted(table, reverse=True):
            print(f"{length:4d} {where}: {message}")
    return problems


DOC_POINTER = re.compile(r"doc/([\w.-]+\.(?:md|rst))(?:, (\w[\w ]*\w))?")


def has_heading(page, heading):
    """Whether the doc page has a section of that title: in reStructuredText the title line
    followed by its underline (one punctuation character repeated), in Markdown a '## ' line."""
    lines = page.read_text().splitlines()
    if page.suffix == ".rst":
        return any(lines[k] == heading and len(lines[k + 1]) >= len(heading) and len(set(lines[k + 1])) == 1
                   and not lines[k + 1][0].isalnum() for k in range(len(lines) - 1))
    return f"## {heading}" in lines


def check_doc_pointers(src, doc):
    """Every doc page a message names exists, with the heading it names ("doc/fix_wire.rst,
    Errors" needs a section 'Errors' in doc/fix_wire.rst)."""
    problems = []
    for path in sorted(src.rglob("*")):
        if path.suffix not in (".h", ".cpp"):
            continue
        # the messages (adjacent literals joined), and every other literal naming a page: one
        # passed to a helper that puts it in a message (read_restart_block's "doc/fix_nscd.rst")
        text = strip_comments_and_strings(path.read_text(), keep_strings=True)
        literals = [(line_of(text, m.start()), None, m.group(1)) for m in LITERAL.finditer(text)
                    if DOC_POINTER.search(m.group(1))]
        for line, _, message in messages(path) + literals:
            for page, heading in DOC_POINTER.findall(message):
                where = f"{path.relative_to(src.parent)}:{line}"
                if not (doc / page).is_file():
                    problems.append(f"{where}: the message names doc/{page}, which does not exist")
                elif heading and not has_heading(doc / page, heading):
                    problems.append(f"{where}: the message names the section '{heading}' of doc/{page}, "
                                    f"which has no section '{heading}'")
    return problems


# ---------------------------------------------------------------- the package's namespace

def blank_preprocessor(text):
    """The text with preprocessor lines (and their continuations) blanked, lines kept."""
    return re.sub(r"^[ \t]*#(?:[^\n]*\\\n)*[^\n]*", lambda m: re.sub(r"[^\n]", " ", m.group(0)), text, flags=re.M)


def without_template_heads(head):
    """`head` with its `template <...>` prefixes removed (angle brackets balanced)."""
    while True:
        m = re.match(r"\s*template\s*<", head)
        if not m:
            return head
        depth, i = 1, m.end()
        while i < len(head) and depth:
            depth += {"<": 1, ">": -1}.get(head[i], 0)
            i += 1
        head = head[i:]


CLASS_HEAD = re.compile(r"^\s*(?:class|struct|union)\s+(?:\w+\s+)*?([\w:]+)\s*(?:final\s*)?(?::(.*))?$", re.S)


def lammps_derived_classes(src):
    """The classes of src/ derived from a LAMMPS class, directly or through another of them
    (the styles and their package bases, e.g. ComputeNSCDGrainSums)."""
    heads = []
    for path in src.glob("*.h"):
        text = strip_comments_and_strings(path.read_text())
        heads += re.findall(r"\b(?:class|struct)\s+(\w+)\s*(?:final\s*)?:([^{;]*)\{", text)
    derived = set()
    grown = True
    while grown:
        grown = False
        for name, bases in heads:
            base_names = set(re.findall(r"\w+", bases))
            if name not in derived and (re.search(r"\b" + LAMMPS_BASES + r"\b", bases) or base_names & derived):
                derived.add(name)
                grown = True
    return derived


def allowed_in_lammps_ns(head, derived):
    """Why a definition whose head (the text before its '{') stands directly in LAMMPS_NS is
    not allowed there, or None: a style or a class derived from a LAMMPS class (`derived`),
    or the definition of a nested class of one (`struct FixWire::Lib`)."""
    m = CLASS_HEAD.match(without_template_heads(head))
    if not m:
        return "a helper (function, enum or variable) directly in LAMMPS_NS"
    name = m.group(1)
    if "::" in name or name in derived:
        return None
    return f"the helper class {name} directly in LAMMPS_NS"


def namespace_problems(path, label, derived):
    """Breaches of rule 4 in one file (labelled `label` in the messages)."""
    text = blank_preprocessor(strip_comments_and_strings(path.read_text()))
    problems = []
    stack = []    # per open '{': ('ns', name) for a namespace, ('other', '') otherwise
    start = 0

    def where(offset):
        return f"{label}:{line_of(text, offset)}"

    def names():
        return [n for kind, n in stack if kind == "ns"]

    for i, ch in enumerate(text):
        if ch not in "{};":
            continue
        head = text[start:i]
        at = start + len(head) - len(head.lstrip())
        head = " ".join(head.split())
        inside_other = any(kind == "other" for kind, _ in stack)
        spaces = names()
        if ch == "{":
            ns = re.match(r"(?:inline\s+)?namespace\s*([\w:]*)\s*$", head)
            if ns and not inside_other:
                name = ns.group(1)
                if name and not spaces and name not in ("LAMMPS_NS", LIB_NAMESPACE):
                    problems.append(f"{where(at)}: top-level namespace {name}: the package's helpers go in "
                                    f"LAMMPS_NS::{PACKAGE_NAMESPACE}")
                elif name and spaces == ["LAMMPS_NS"] and name != PACKAGE_NAMESPACE:
                    problems.append(f"{where(at)}: namespace {name} in LAMMPS_NS: the package keeps its helpers in "
                                    f"one namespace, LAMMPS_NS::{PACKAGE_NAMESPACE} (doc/build.md)")
                elif name and spaces[:1] == ["LAMMPS_NS"] and len(spaces) > 1:
                    problems.append(f"{where(at)}: namespace {name} inside {'::'.join(spaces)}: the package keeps its "
                                    f"helpers in one namespace, LAMMPS_NS::{PACKAGE_NAMESPACE}")
                stack.append(("ns", name))
            else:
                if not inside_other:
                    if spaces == ["LAMMPS_NS"]:
                        why = allowed_in_lammps_ns(head, derived)
                        if why:
                            problems.append(f"{where(at)}: {why}: put it in LAMMPS_NS::{PACKAGE_NAMESPACE}: {head[:80]}")
                    elif spaces[:1] == [LIB_NAMESPACE]:
                        problems.append(f"{where(at)}: a definition in lib/'s namespace {LIB_NAMESPACE} "
                                        f"(src/ only forward-declares lib/'s types): {head[:80]}")
                    elif (not spaces and "(" in head
                          and not re.match(r"(static|namespace)\b", without_template_heads(head).strip())):
                        name = re.match(r"[^(]*?([\w:~]+)\s*\(", head)
                        if name and "::" not in name.group(1) and "=" not in head[:name.start(1)]:
                            problems.append(f"{where(at)}: the function {name.group(1)} at global scope (external "
                                            f"linkage): make it a member, or put it in an unnamed namespace or "
                                            f"in LAMMPS_NS::{PACKAGE_NAMESPACE}")
                stack.append(("other", ""))
            start = i + 1
        elif ch == "}":
            if stack:
                stack.pop()
            start = i + 1
        else:    # ';'
            if not inside_other and head and spaces == ["LAMMPS_NS"]:
                forward = re.match(r"(?:template\s*<[^;]*>\s*)?(?:class|struct)\s+\w+$", head)
                if not forward:
                    problems.append(f"{where(at)}: a declaration directly in LAMMPS_NS: put it in "
                                    f"LAMMPS_NS::{PACKAGE_NAMESPACE}: {head[:80]}")
            elif not inside_other and head and spaces[:1] == [LIB_NAMESPACE]:
                if not re.match(r"(?:class|struct)\s+\w+$", head):
                    problems.append(f"{where(at)}: a declaration in lib/'s namespace {LIB_NAMESPACE} "
                                    f"(src/ only forward-declares lib/'s types): {head[:80]}")
            start = i + 1
    return problems


def check_namespaces(src):
    problems = []
    derived = lammps_derived_classes(src)
    for path in sorted(list(src.glob("*.h")) + list(src.glob("*.cpp"))):
        problems += namespace_problems(path, f"src/{path.name}", derived)
    return problems


def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 2
    repo = pathlib.Path(argv[1])
    src, lib = repo / "src", repo / "lib"
    problems = check_member_initialisers(src) + check_k_constants(src, lib) + \
        check_messages(src, "--lengths" in argv) + check_doc_pointers(src, repo / "doc") + \
        check_namespaces(src)
    for p in problems:
        print(p)
    if problems:
        print(f"{len(problems)} breach(es) of LAMMPS' style rules (tools/lammps_style.py)")
        return 1
    print("src/ keeps LAMMPS' style rules: member initialisers, constant names, message lengths and their doc pages, "
          f"helpers in LAMMPS_NS::{PACKAGE_NAMESPACE}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
