"""Every citation of the book is the book's (CONVENTIONS, "Citations are the book's").

The book's table of contents, every section number with its title, is `BOOK_TOC.md` beside
`BOOK_OUTLINE.md` (a copy of the project's; `test_toc_copy_is_current` checks the two agree
wherever the shared folder sits beside the clone).  This file reads it and checks:

* **Citations.**  Every "§N", "§N.M", "§N.M.K" in the notebooks (the source of every markdown
  and code cell, never outputs), in `goldman_lib` (docstrings, checker messages, PROBLEMS
  statements, view titles, comments: the whole text of each module), in `benchmarks/`, in
  `scripts/`, in the tests (other than this file) and in README/CONTRIBUTING names a section of
  the book.  Ranges ("§2.2-2.3", "§§8.2–8.5", "§7.2 to 7.3") must have both ends in the book,
  in one chapter, in increasing order; in lists ("§10.3.1, §10.4", "§9.4 and 10.3") every
  item is checked.  "issue 20 §1" names a section of one of the project's issues and is skipped.
* **Numbered headings.**  A notebook heading that starts with a section number ("## 13.3.1
  Translation") carries the book's title for that number, and the number belongs to the
  notebook's chapter.  "Carries" means: after normalising both sides (HTML tags dropped,
  accents dropped, case folded, British spellings read as the book's American ones, every
  character that is not a letter or a digit removed), the book's title appears inside the
  heading's title, so our own words may come before or after it ("13.5 Projections:
  orthogonal projection", "22.3 The z-buffer").  Where the book's title has a parenthetical
  ("z-Buffer (Depth Buffer)", "Constructive Solid Geometry (CSG)") the title without it, or the
  parenthetical alone, is enough; where it has a colon ("Projective Space: The Standard Model")
  the words before the colon are enough; a leading "The"/"A" of the book's title may be left out.
  A heading may name two sections ("13.3.2 Rotation and 13.3.3 Mirror image"): each number
  is checked with the words that follow it.  A heading of our own has no number.  The chapter
  title ("# Chapter 13 — ...") is the course's short name for the chapter; only its number is
  checked (it must be the notebook's).
* **Labels.**  A number can exist and still be the wrong section.  Where a label follows a
  citation directly (a comment header "# -- §13.5 perspective", a view title "§20.2 CSG by ray
  classification"), its first word must not open the title of another section of the same chapter
  while appearing in no title of the cited section, its parents or its subsections: "§13.5
  perspective" names §13.6, "§10.2 dot product" names §10.3.1.  A few citations that were wrong in
  this way (issue 18) are pinned in `PINNED`.

Each check collects every failure and reports them all in one assertion (file, line or cell,
the citation, and what the book has), so one run lists everything to fix.  The parser and the
matcher are tested first on small inline examples, including wrong numbers, a reversed range
and headings with the wrong title, so the whole-repository checks can fail.
"""

import functools
import json
import re
import unicodedata
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
TOC_PATH = ROOT / "BOOK_TOC.md"
SHARED_TOC = ROOT.parent / "shared" / "BOOK_TOC.md"
THIS = Path(__file__).resolve()


# --------------------------------------------------------------------------------------------
# The table of contents

def parse_toc(text):
    """{number: title} from BOOK_TOC.md's text: "### 13 Title" for a chapter, "- 13.3 Title" (at
    any indentation) for a section.  HTML tags in titles (<i>...</i>) are dropped."""
    toc = {}
    for line in text.splitlines():
        m = re.match(r"^\s*(?:- |### )(\d+(?:\.\d+)*) +(.+?)\s*$", line)
        if m:
            toc[m.group(1)] = re.sub(r"<[^>]+>", "", m.group(2)).strip()
    return toc


TOC = parse_toc(TOC_PATH.read_text(encoding="utf-8"))


def key(number):
    return tuple(int(p) for p in number.split("."))


# --------------------------------------------------------------------------------------------
# Citations: "§N.M", ranges and lists

NUM = r"\d+(?:\.\d+)*"
DOTTED = r"\d+\.\d+(?:\.\d+)*"
RANGE_SEP = r"\s*(?:-|–|—|\bto\b)\s*"
LIST_SEP = r"\s*(?:,|;|\band\b|\bor\b|&)\s*"
# A § (or §§), a number, then any run of "- number" (a range) or ", §number" / ", N.M" (a list).
# A bare list item must be dotted ("§9.4 and 10.3"), so "§2.3, 3 levels" reads as §2.3 alone.
CITATION = re.compile(
    rf"§§?\s*(?P<first>{NUM})(?P<rest>(?:{RANGE_SEP}§?{NUM}|{LIST_SEP}(?:§§?\s*{NUM}|{DOTTED}))*)")
ISSUE = re.compile(r"\bissues?\s+\d+(?:'s)?,?\s*$", re.I)
TOKEN = re.compile(rf"(?P<sep>{RANGE_SEP}|{LIST_SEP})§?§?\s*(?P<num>{NUM})")


def range_end(first, last):
    """The last number of a range, read in full: "21.4.2-3" ends at 21.4.3 (a shorter end replaces
    the last parts of the first number); "2.2-2.3" and "7.2-7.3.3" are already in full."""
    a, b = first.split("."), last.split(".")
    return ".".join(a[:len(a) - len(b)] + b) if len(b) < len(a) else last


def citations(text, bare=True):
    """Every citation in ``text`` as (line number, the text cited, [items]): an item is a number
    (str) or a range (first, last).  With ``bare``, a "§" not followed by a number is an item
    ``None`` (the tests and the contributors' guide write "§{chapter}", "§NN.k" as templates)."""
    found = []
    for m in CITATION.finditer(text):
        if ISSUE.search(text, max(0, m.start() - 24), m.start()):
            continue  # "issue 20 §1" is a section of one of the project's issues, not of the book
        items = [m.group("first")]
        for t in TOKEN.finditer(m.group("rest")):
            if re.fullmatch(RANGE_SEP, t.group("sep")):
                start = items.pop()
                start = start if isinstance(start, str) else start[1]
                items.append((start, range_end(start, t.group("num"))))
            else:
                items.append(t.group("num"))
        found.append((text.count("\n", 0, m.start()) + 1, m.group(0).strip(), items))
    for m in re.finditer(r"§§?(?!§|\s*\d)", text) if bare else ():
        found.append((text.count("\n", 0, m.start()) + 1, text[m.start():m.start() + 12].split("\n")[0], [None]))
    return found


def citation_problems(item, toc=None):
    """What is wrong with one item of a citation (a list of strings; empty when it is right)."""
    toc = TOC if toc is None else toc
    if item is None:
        return ["§ without a section number"]
    if isinstance(item, str):
        return [] if item in toc else [f"{item} is not a section of the book"]
    first, last = item
    problems = [f"{n} is not a section of the book" for n in (first, last) if n not in toc]
    if not problems:
        if first.split(".")[0] != last.split(".")[0]:
            problems.append(f"the range {first}-{last} spans two chapters")
        elif key(first) >= key(last):
            problems.append(f"the range {first}-{last} does not increase")
    return problems


def where_book_has(item, toc=None):
    """A short note of what the book has near a wrong number: its title, or the chapter's sections."""
    toc = TOC if toc is None else toc
    numbers = [item] if isinstance(item, str) else list(item or [])
    notes = []
    for n in numbers:
        if n in toc:
            notes.append(f"{n} is '{toc[n]}'")
        else:
            parent = n.rsplit(".", 1)[0] if "." in n else None
            siblings = [k for k in toc if parent and k.rsplit(".", 1)[0] == parent and k.count(".") == n.count(".")]
            if siblings:
                notes.append(f"{parent} has {', '.join(siblings)}")
            elif n.split(".")[0] in toc:
                notes.append(f"chapter {n.split('.')[0]} is '{toc[n.split('.')[0]]}'")
    return "; ".join(notes)


def check_text(text, where, toc=None, bare=True):
    """Failures (strings) of every citation in ``text``; ``where(line)`` names the place."""
    failures = []
    for line, cited, items in citations(text, bare):
        for item in items:
            for problem in citation_problems(item, toc):
                note = where_book_has(item, toc)
                failures.append(f"{where(line)}: '{cited}': {problem}" + (f" (the book: {note})" if note else ""))
    return failures


# A label right after a citation ("# -- §13.5 perspective", a view title "§20.2 CSG by ...") whose
# first word opens the title of another section of the same chapter names that other section:
# "§13.5 perspective" is §13.6's, "§10.2 dot product" is §10.3.1's.
LABEL_SKIP = {"the", "a", "an", "and", "of", "in", "on", "for", "to", "with", "by", "from", "its", "our"}


def family(number, toc=None):
    """The section, its ancestors and its descendants."""
    toc = TOC if toc is None else toc
    return [k for k in toc if k == number or k.startswith(number + ".") or number.startswith(k + ".")]


def first_word(text):
    words = [w for w in re.findall(r"[a-z]+", normal_words(text)) if w not in LABEL_SKIP]
    return words[0] if words else None


def _label_index(number, toc):
    """(stems of the title words of the section's family, {stem of the first title word of another
    section of the chapter: that section})."""
    own = family(number, toc)
    stems = {w[:5] for k in own for w in re.findall(r"[a-z]+", normal_words(toc[k]))}
    others = {}
    for k, title in toc.items():
        if k.split(".")[0] == number.split(".")[0] and k not in own and first_word(title):
            others.setdefault(first_word(title)[:5], k)
    return stems, others


_book_label_index = functools.lru_cache(maxsize=None)(lambda number: _label_index(number, TOC))


def label_problems(text, toc=None):
    """(line, citation, label word, other section) for labels that name another section of the chapter."""
    toc = TOC if toc is None else toc
    found = []
    for m in CITATION.finditer(text):
        if ISSUE.search(text, max(0, m.start() - 24), m.start()):
            continue
        items = citations(m.group(0))[0][2]
        label = re.match(r"[ \t]*:?[ \t]+([A-Za-z][\w -]{0,40})", text[m.end():m.end() + 48])
        if len(items) != 1 or not isinstance(items[0], str) or items[0] not in toc or not label:
            continue
        word, number = first_word(label.group(1)), items[0]
        if word is None:
            continue
        stems, others = _book_label_index(number) if toc is TOC else _label_index(number, toc)
        if word[:5] not in stems and word[:5] in others:
            found.append((text.count("\n", 0, m.start()) + 1, m.group(0).strip(), word, others[word[:5]]))
    return found


# --------------------------------------------------------------------------------------------
# Numbered headings

SPELLING = [("colour", "color"), ("labell", "label"), ("modell", "model"), ("centre", "center"),
            ("behaviour", "behavior")]


def normal_words(text):
    """Lower case words without accents or HTML tags (the book's spelling), spaces kept."""
    text = re.sub(r"<[^>]+>", "", text)
    text = unicodedata.normalize("NFKD", text).encode("ascii", "ignore").decode().lower()
    for ours, book in SPELLING:
        text = text.replace(ours, book)
    return text


def normal(text):
    """Letters and digits only, lower case, no accents or HTML tags, the book's spelling."""
    return re.sub(r"[^a-z0-9]", "", normal_words(text))


def title_forms(book_title):
    """The normalised forms of a book title a heading may carry (see the module docstring)."""
    forms = {book_title, book_title.split(":")[0]}
    m = re.match(r"^(.*?)\s*\(([^)]*)\)\s*$", book_title)
    if m:
        forms |= {m.group(1), m.group(2)}
    forms |= {re.sub(r"^(?:the|a|an)\s+", "", f, flags=re.I) for f in forms}
    return {normal(f) for f in forms if normal(f)}


def carries_title(heading_title, book_title):
    """True when ``heading_title`` carries ``book_title`` (the rule of the module docstring)."""
    heading = normal(heading_title)
    return any(form in heading for form in title_forms(book_title))


HEADING = re.compile(r"^(#{1,6})[ \t]+§?(\d+\.\d+(?:\.\d+)*)\.?[ \t]+(.+?)\s*$", re.M)
# A further section number inside a heading: "13.3.2 Rotation, and 13.3.3 mirror image".
INNER = re.compile(r"(?:^|[\s,;:(]|\band\b)\s*§?(\d+\.\d+(?:\.\d+)*)\.?\s+(?=\S)")


def heading_parts(title_after_number, number):
    """[(number, its words)] for a heading, splitting at further section numbers in its title."""
    parts, pos, current = [], 0, number
    for m in INNER.finditer(title_after_number):
        parts.append((current, title_after_number[pos:m.start()]))
        current, pos = m.group(1), m.end()
    parts.append((current, title_after_number[pos:]))
    return parts


def check_headings(markdown, where, chapter=None, toc=None):
    """Failures of the numbered headings in a markdown cell's source."""
    toc = TOC if toc is None else toc
    failures = []
    for m in HEADING.finditer(markdown):
        line = markdown.count("\n", 0, m.start()) + 1
        heading = m.group(0).strip()
        for number, words in heading_parts(m.group(3), m.group(2)):
            if number not in toc:
                failures.append(f"{where(line)}: heading '{heading}': {number} is not a section of the book "
                                f"({where_book_has(number, toc) or 'no such chapter'}); material of our own has no number")
            elif chapter is not None and number.split(".")[0] != str(chapter):
                failures.append(f"{where(line)}: heading '{heading}': {number} is not a section of chapter {chapter}")
            elif not carries_title(words, toc[number]):
                failures.append(f"{where(line)}: heading '{heading}' does not carry the book's title: "
                                f"{number} is '{toc[number]}'")
    for m in re.finditer(r"^#{1,6}[ \t]+Chapter[ \t]+(\d+)\b", markdown, re.M):
        if chapter is not None and m.group(1) != str(chapter):
            line = markdown.count("\n", 0, m.start()) + 1
            failures.append(f"{where(line)}: '{m.group(0)}' in the notebook of chapter {chapter}")
    return failures


# --------------------------------------------------------------------------------------------
# Where citations live

NOTEBOOKS = sorted((ROOT / "course").glob("*.ipynb"))
SOURCES = sorted(
    [p for d in ("goldman_lib", "benchmarks", "scripts", "tests") for p in (ROOT / d).rglob("*.py")
     if p.resolve() != THIS and ".ipynb_checkpoints" not in p.parts]
    + [ROOT / "README.md", ROOT / "CONTRIBUTING.md"])


@functools.lru_cache(maxsize=None)
def notebook_cells(path):
    """[(index, cell type, source)] of a notebook's cells (read once per run)."""
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    return [(i, cell.get("cell_type"), "".join(src) if isinstance(src, list) else src)
            for i, cell in enumerate(cells) for src in [cell.get("source", "")]]


@functools.lru_cache(maxsize=None)
def source_text(path):
    return path.read_text(encoding="utf-8")


def chapter_of(path):
    m = re.match(r"(\d\d)_", path.name)
    return int(m.group(1)) if m else None


def rel(path):
    return path.relative_to(ROOT).as_posix()


def report(failures):
    return f"{len(failures)} citation(s) disagree with BOOK_TOC.md:\n" + "\n".join(failures)


# --------------------------------------------------------------------------------------------
# The parser and the matcher on small examples (these make the checks below able to fail)

def items_of(text):
    return [items for _, _, items in citations(text)]


def test_toc_is_read_with_every_level():
    assert TOC["13"] == "Matrix Representations for Affine and Projective Transformations"
    assert TOC["13.3.1"] == "Translation"
    assert TOC["11.4.1.2"] == "Distance between a Point and a Line"
    assert TOC["14.2"] == "Projective Space: The Standard Model"  # <i>...</i> dropped
    assert "13.5.2" not in TOC and "13.8" not in TOC
    assert len([k for k in TOC if "." not in k]) == 30


def test_toc_copy_is_current():
    if not SHARED_TOC.exists():
        pytest.skip("the shared folder is not beside this clone; the repository's BOOK_TOC.md is used")
    assert SHARED_TOC.read_text() == TOC_PATH.read_text(), "copy ../shared/BOOK_TOC.md to BOOK_TOC.md"


def test_citations_are_parsed_with_ranges_and_lists():
    assert items_of("the matrix (Goldman §13.3.1).") == [["13.3.1"]]
    assert items_of("see §4.7.3. Then") == [["4.7.3"]]
    assert items_of("(§§2.2-2.3)") == [[("2.2", "2.3")]]
    assert items_of("(§8.2–8.5), §7.2 to 7.3") == [[("8.2", "8.5")], [("7.2", "7.3")]]
    assert items_of("§10.3.1, §10.4 and 9.4. See §9, Appendix A") == [["10.3.1", "10.4", "9.4"], ["9"]]
    assert items_of("§21.4.2-3, §2.2-3") == [[("21.4.2", "21.4.3"), ("2.2", "2.3")]]
    assert items_of("§9.3, Appendix B and §2.3, 3 levels") == [["9.3"], ["2.3"]]
    assert items_of("§ 13.6.2") == [["13.6.2"]]
    assert items_of("§§15.3.4-15.3.5 and §16.3-16.6") == [[("15.3.4", "15.3.5"), ("16.3", "16.6")]]
    assert items_of("(issue 20 §1; issue 17's §2) and §16.5") == [["16.5"]]
    assert items_of("cite §NN.k here") == [[None]]
    assert citations("cite §NN.k here", bare=False) == []
    assert [line for line, _, _ in citations("a\nb §1.2\n\nc §3")] == [2, 4]


def test_wrong_numbers_reversed_ranges_and_crossed_chapters_fail():
    assert check_text("Goldman §13.3.1, §10.3.1 and §§2.2-2.3", str) == []
    bad = {"§13.8": "13.8 is not a section", "§13.5.2": "13.5.2 is not a section",
           "§10.3.1, 10.9": "10.9 is not a section", "§2.3-2.2": "does not increase",
           "§8.4-9.2": "spans two chapters", "§31": "31 is not a section", "§x": "without a section number"}
    for text, problem in bad.items():
        failures = check_text(text, lambda line: "here")
        assert len(failures) == 1 and problem in failures[0], (text, failures)
    assert "13.5 has 13.5.1" in check_text("§13.5.2", str)[0]


@pytest.mark.parametrize("heading, book", [
    ("Translation", "Translation"),
    ("Projections: orthogonal projection", "Projections"),
    ("The z-buffer", "z-Buffer (Depth Buffer)"),
    ("Depth buffer", "z-Buffer (Depth Buffer)"),
    ("CSG", "Constructive Solid Geometry (CSG)"),
    ("Constructive solid geometry", "Constructive Solid Geometry (CSG)"),
    ("The RGB colour model", "The RGB Color Model"),
    ("RGB color model", "The RGB Color Model"),
    ("Tensor-product Bézier patches", "Tensor Product Bezier Patches"),
    ("Labelling and locality in the global de Boor algorithm", "Labeling and Locality in the Global de Boor Algorithm"),
    ("BSP trees", "BSP-Tree"),
    ("Projective space", "Projective Space: The Standard Model"),
    ("Shooting", "Shooting: Progressive Refinement"),
])
def test_headings_that_carry_the_book_title(heading, book):
    assert carries_title(heading, book)


@pytest.mark.parametrize("heading, book", [
    ("Translation", "Linear Transformation Matrices and Translation Vectors"),
    ("Perspective", "Projections"),
    ("Normals", "Surface Normals"),
    ("Differentiation", "Differentiating the de Casteljau Algorithm"),
    ("Progressive refinement", "Shooting: Progressive Refinement"),
    ("The questions of this chapter", "Motivating Questions"),
    ("Fast Phong shading: diffuse", "Fast Phong Shading and Diffuse Reflection"),
])
def test_headings_with_another_title_fail(heading, book):
    assert not carries_title(heading, book)


def test_heading_checks_on_examples():
    where = lambda line: f"line {line}"  # noqa: E731
    assert check_headings("## 13.3.1 Translation\n### 13.3.2 Rotation, and 13.3.3 mirror image", where, 13) == []
    assert check_headings("## What you will learn\n### Exercise 1.1 — a star\n# Chapter 13 — Matrices", where, 13) == []
    wrong = check_headings("text\n## 13.2 Translation", where, 13)
    assert len(wrong) == 1 and "line 2" in wrong[0] and "'Linear Transformation Matrices" in wrong[0]
    assert "is not a section of the book" in check_headings("## 13.5.2 Perspective", where, 13)[0]
    assert "not a section of chapter 13" in check_headings("## 12.3 Rigid motions", where, 13)[0]
    two = check_headings("### 13.3.2 Rotation and 13.3.3 Scaling", where, 13)
    assert len(two) == 1 and "13.3.3 is 'Mirror Image'" in two[0]
    assert check_headings("# Chapter 12 — Formulas", where, 13)
    assert check_headings("## 13.5 Projections", where, 13) == []
    assert check_headings("## 13.5 Perspective", where, 13)


def test_labels_after_citations_on_examples():
    assert label_problems("# -- §13.5 perspective ----") == [(1, "§13.5", "perspective", "13.6")]
    assert label_problems('x\ntitle="§10.2 the dot product"') == [(2, "§10.2", "dot", "10.3.1")]
    assert label_problems("# -- §13.6 perspective\n# -- §13.5 projections\n§10.3.1 dot product") == []
    assert label_problems("§13.5: orthogonal projection; (§13.5), perspective; §13.3.2 rotation") == []
    assert label_problems("§16.5 halfway vector, §20.2 CSG by ray classification") == []


# --------------------------------------------------------------------------------------------
# The repository

def test_every_notebook_citation_names_a_section_of_the_book():
    failures = []
    for path in NOTEBOOKS:
        for i, kind, src in notebook_cells(path):
            failures += check_text(src, lambda line, i=i, kind=kind: f"{rel(path)} cell {i} ({kind}) line {line}")
    assert not failures, report(failures)


def test_every_library_benchmark_script_and_test_citation_names_a_section_of_the_book():
    failures = []
    for path in SOURCES:
        # A bare "§" is a template in the tests, scripts and guides ("§{chapter}", "§NN.k").
        bare = rel(path).startswith(("goldman_lib/", "benchmarks/"))
        failures += check_text(source_text(path), lambda line, path=path: f"{rel(path)}:{line}",
                               bare=bare)
    assert not failures, report(failures)


def test_every_numbered_notebook_heading_carries_the_book_title():
    failures = []
    for path in NOTEBOOKS:
        for i, kind, src in notebook_cells(path):
            if kind == "markdown":
                failures += check_headings(src, lambda line, i=i: f"{rel(path)} cell {i} line {line}",
                                           chapter_of(path))
    assert not failures, report(failures)


def test_labels_after_citations_name_the_cited_section():
    """"§13.5 perspective" in a comment header or a view title names §13.6: the label's first word
    opens another section's title of the chapter and is in no title of the cited section's family."""
    failures = []
    places = [(f"{rel(p)} cell {i}", src) for p in NOTEBOOKS for i, _, src in notebook_cells(p)]
    places += [(rel(p), source_text(p)) for p in SOURCES]
    for where, text in places:
        failures += [f"{where} line {line}: '{cited} {word}...': '{word}' is the book's {k} '{TOC[k]}', not "
                     f"{cited}'s '{TOC[cited.lstrip('§ ')]}'" for line, cited, word, k in label_problems(text)]
    assert not failures, report(failures)


def test_the_places_are_scanned():
    """The scan reaches the library's modules, its exercise checkers, views, and the benchmarks."""
    names = {rel(p) for p in SOURCES}
    assert {"goldman_lib/vectors.py", "goldman_lib/exercises/ch13.py", "goldman_lib/views/transforms.py",
            "benchmarks/bench_vectors.py"} <= names
    assert len(NOTEBOOKS) == 31


# Citations whose numbers exist but were wrong for what they cite (issue 18): pinned, so they
# stay right.  Each: the object, the section its docstring must cite, a section it must not.
PINNED = [
    ("goldman_lib.vectors", "dot", "§10.3.1", "§10.2"),
    ("goldman_lib.transforms", "translation", "§13.3.1", "§13.2"),
    ("goldman_lib.transforms", "orthogonal_projection", "§13.5", "§13.6"),
    ("goldman_lib.transforms", "perspective", "§13.6", "§13.5"),
    ("goldman_lib.lighting", "Light", "§16.4", "§16.1"),
]


@pytest.mark.parametrize("module, name, cite, not_cite", PINNED, ids=[f"{m}.{n}" for m, n, _, _ in PINNED])
def test_pinned_citations(module, name, cite, not_cite):
    import importlib

    doc = getattr(importlib.import_module(module), name).__doc__
    assert cite in doc and not re.search(re.escape(not_cite) + r"(?![\d.]*\d)", doc), doc[:200]
