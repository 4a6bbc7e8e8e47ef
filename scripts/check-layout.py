#!/usr/bin/env python3
"""Checks the header layout the house style asks for: no header under include/ is over 700 lines,
and every public algorithm header (include/hmira/algorithms/<family>/<name>.hpp, not detail/)
declares a public function within its first 100 lines, so a reader meets the entry point first.
Forwarding headers (only #include lines), *_common.hpp and headers that declare only types
are exempt from the second rule. `--list` prints each header's first public function line."""
import pathlib, re, sys

root = pathlib.Path(__file__).resolve().parent.parent / 'include' / 'hmira'
max_lines, entry_within = 700, 100
# A function declared at namespace scope: column 0, a return type, a name, an opening parenthesis.
decl = re.compile(r'^(?:\[\[nodiscard\]\]\s+)?(?:(?:inline|constexpr|static)\s+)*'
                  r'(?!return\b|using\b|namespace\b|enum\b|struct\b|class\b|template\b|concept\b)'
                  r'[\w:<>,\s*&]+?\b(\w+)\s*\(')
helpers = {'enum_names', 'to_string', 'from_string', 'operator'}
errors, found = [], []
for path in sorted(root.rglob('*.hpp')):
    rel = path.relative_to(root.parent.parent)
    lines = path.read_text(encoding='utf-8').split('\n')
    if len(lines) > max_lines:
        errors.append(f'{rel}: {len(lines)} lines (at most {max_lines})')
    parts = path.relative_to(root).parts
    if parts[0] != 'algorithms' or 'detail' in parts or len(parts) != 3 or path.name.endswith('_common.hpp'):
        continue
    code = [l for l in lines if l.strip() and not l.lstrip().startswith(('//', '#'))]
    if not code:
        continue  # a forwarding header
    depth_detail, first = 0, None
    for i, line in enumerate(lines, 1):
        if re.match(r'^namespace\s+[\w:]*detail\b', line):
            depth_detail += 1
        elif depth_detail and re.match(r'^}\s*//\s*namespace\s+[\w:]*detail', line):
            depth_detail -= 1
        elif not depth_detail:
            # A template's entry point counts from its `template <...>` line; the declaration
            # may follow on the next lines, after a requires-clause.
            start = i
            if line.startswith('template'):
                rest = ' '.join(l.strip() for l in lines[i - 1:i + 3])
                m = re.search(r'>\s*(?:requires\s+[\w:<>, &|()!]+?\s+)?[\w:<>,*& ]+?\b(\w+)\s*\(', rest)
                if m and m.group(1) not in helpers and not rest.split('>', 1)[-1].lstrip().startswith(
                        ('struct', 'class', 'concept', 'using', 'inline constexpr', 'constexpr bool')):
                    first = start
                    break
                continue
            m = decl.match(line)
            if m and m.group(1) not in helpers:
                first = i
                break
    found.append(f"{rel}: {first}")
    if first is None:
        continue  # types and names only (such as an option enum): no entry point to show
    if first > entry_within:
        errors.append(f'{rel}: first public function at line {first} (within the first {entry_within} lines)')
if len(sys.argv) > 1 and sys.argv[1] == "--list":
    print("\n".join(found))
for e in errors:
    print(e)
sys.exit(1 if errors else 0)
