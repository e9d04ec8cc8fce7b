#!/usr/bin/env python3
"""Files and functions over the house's sizes (issue 39): a source file over 800 lines, a function
over 150.

Reads every .cpp/.h/.cl under the folders given (default: engine/src, frontends, plugins). A
function is a brace block opened at namespace or class level after a parameter list (not a
class, struct, enum, namespace or initialiser); its length runs from the line of its name to its
closing brace, lambdas and nested blocks included. Comments, strings and character literals are
blanked before braces are counted. Prints one line per file or function over the bar; exits 1
when any is not named in the allow file (tests/tools/code_sizes.allow: one `path` or
`path:function` a line, then `#` and why it is kept: a table, a kernel essay).
Usage: code_sizes.py [ROOT] [--allow FILE] [--file-lines N] [--function-lines N]
"""
import os
import re
import sys

args = sys.argv[1:]
def option(name, default):
    return args[args.index(name) + 1] if name in args else default
here = os.path.dirname(os.path.abspath(__file__))
root = next((a for i, a in enumerate(args) if not a.startswith("--") and (i == 0 or not args[i - 1].startswith("--"))),
            os.path.join(here, "..", ".."))
allow_file = option("--allow", os.path.join(here, "code_sizes.allow"))
file_bar = int(option("--file-lines", 800))
function_bar = int(option("--function-lines", 150))

allowed = set()
if os.path.exists(allow_file):
    for line in open(allow_file, encoding="utf-8"):
        entry = line.split("#", 1)[0].strip()
        if entry:
            allowed.add(entry)

def blank(text):
    """Comments, strings and character literals as spaces (newlines kept), raw strings included."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i)); i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j])); i = j
        elif text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            m = re.match(r'R"([^(\s]{0,16})\(', text[i:])
            if not m:
                out.append(c); i += 1; continue
            end = ")" + m.group(1) + '"'
            j = text.find(end, i + m.end())
            j = n if j < 0 else j + len(end)
            out.append(re.sub(r"[^\n]", " ", text[i:j])); i = j
        elif c in "\"'" and not (c == "'" and i > 0 and text[i - 1].isalnum()):  # 1'000 digit separators
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(" " * (j - i)); i = j
        else:
            out.append(c); i += 1
    return "".join(out)

NOT_FUNCTION = re.compile(r"\b(class|struct|union|enum|namespace|if|for|while|switch|catch|do|else|return)\b")

def functions(text):
    """(name, first line, last line) of every function body at namespace or class level."""
    code = blank(text)
    found, stack, head_start = [], [], 0  # stack: (kind, start line, name)
    line_of = lambda pos: code.count("\n", 0, pos) + 1
    for pos, c in enumerate(code):
        if c in ";":
            head_start = pos + 1
        elif c == "{":
            head = code[head_start:pos]
            outer_is_scope = all(kind == "scope" for kind, _, _ in stack)
            kind = "block"
            if outer_is_scope:
                if "(" in head and not NOT_FUNCTION.search(head.split("(", 1)[0]) and not head.rstrip().endswith("="):
                    kind = "function"
                elif NOT_FUNCTION.search(head) or head.strip().startswith("extern"):
                    kind = "scope"
            name = ""
            if kind == "function":
                m = re.search(r"([~\w:]+(?:operator\s*\S+)?)\s*\(", head)
                name = m.group(1) if m else "?"
                first = head_start + len(head) - len(head.lstrip())
                stack.append((kind, line_of(first), name))
            else:
                stack.append((kind, line_of(pos), name))
            head_start = pos + 1
        elif c == "}":
            if stack:
                kind, start, name = stack.pop()
                if kind == "function":
                    found.append((name, start, line_of(pos)))
            head_start = pos + 1
    return found

over = []
folders = [os.path.join(root, d) for d in ("engine/src", "frontends", "plugins", "engine/include")]
for folder in folders:
    for dirpath, _, files in os.walk(folder):
        for f in sorted(files):
            if not f.endswith((".cpp", ".h", ".cl", ".inc")):
                continue
            path = os.path.join(dirpath, f)
            rel = os.path.relpath(path, root)
            text = open(path, encoding="utf-8", errors="replace").read()
            lines = text.count("\n")
            if lines > file_bar:
                over.append((rel, f"{rel}: {lines} lines", rel in allowed))
            for name, first, last in functions(text):
                length = last - first + 1
                if length > function_bar:
                    key = f"{rel}:{name}"
                    over.append((key, f"{rel}:{first}: {name}: {length} lines", key in allowed))

bad = 0
for key, line, ok in sorted(over):
    print(line + ("  (kept: see code_sizes.allow)" if ok else ""))
    bad += not ok
print(f"{bad} over the bars ({file_bar} lines a file, {function_bar} a function) and not kept")
sys.exit(1 if bad else 0)
