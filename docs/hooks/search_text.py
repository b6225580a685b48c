"""The search index as a reader wants its snippets: math as plain text, no repeated code.

Material's search shows the text of a page as it was written: TeX source (``\\frac{...}``)
and, on a notebook's page, every code cell twice. After the build the index is rewritten.
"""

from __future__ import annotations

import html
import json
import re
from pathlib import Path

_SUPERSCRIPTS = str.maketrans("0123456789+-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻")

_SUBSCRIPTS = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")

_TEX_SYMBOLS = {
    "times": "×",
    "cdot": "·",
    "cdots": "⋯",
    "ldots": "…",
    "dots": "…",
    "theta": "θ",
    "alpha": "α",
    "beta": "β",
    "gamma": "γ",
    "epsilon": "ε",
    "varepsilon": "ε",
    "lambda": "λ",
    "pi": "π",
    "Rightarrow": "⇒",
    "rightarrow": "→",
    "to": "→",
    "approx": "≈",
    "le": "≤",
    "leq": "≤",
    "ge": "≥",
    "geq": "≥",
    "ne": "≠",
    "neq": "≠",
    "pm": "±",
    "infty": "∞",
    "perp": "⊥",
    "in": "∈",
    "lVert": "‖",
    "rVert": "‖",
    "|": "‖",
    "{": "{",
    "}": "}",
    "qquad": "  ",
    "quad": " ",
    ",": " ",
    ";": " ",
    ":": " ",
    "!": "",
    " ": " ",
    "\\": "; ",
}

_TEX_DROP = {"left", "right", "displaystyle", "big", "Big", "bigl", "bigr", "Bigl", "Bigr"}


def tex_to_text(tex: str) -> str:
    r"""TeX as readable plain text for search snippets.

    >>> tex_to_text(r"N = U \times V,\quad \hat n = N / |N|")
    'N = U × V, n̂ = N / |N|'
    >>> tex_to_text(r"\frac{|\mathbf{N}|^2}{4} = \sqrt{x_{1}^{2}}")
    '|N|²/4 = √(x₁²)'
    >>> tex_to_text(r"|U|\,|V|\,\sin\theta")
    '|U| |V| sin θ'
    """
    s = re.sub(r"\\(?:begin|end)\{[a-z*]+\}", " ", tex)
    for _ in range(6):  # innermost first: no braces inside the arguments
        s = re.sub(
            r"\\(?:mathbf|mathrm|mathit|text|textbf|operatorname|boldsymbol)\{([^{}]*)\}", r"\1", s
        )
        s = re.sub(r"\\(?:hat|widehat)\{([^{}]*)\}", "\\1\u0302", s)
        s = re.sub(r"\\vec\{([^{}]*)\}", "\\1\u20d7", s)
        s = re.sub(r"\\sqrt\{([^{}]*)\}", r"√(\1)", s)
        s = re.sub(
            r"\\[dt]?frac\{([^{}]*)\}\{([^{}]*)\}",
            lambda m: "/".join(p if re.fullmatch(r"[^ +\-]*", p) else f"({p})" for p in m.groups()),
            s,
        )
        s = re.sub(r"\^\{([0-9+\-]+)\}", lambda m: m.group(1).translate(_SUPERSCRIPTS), s)
        s = re.sub(r"_\{([0-9]+)\}", lambda m: m.group(1).translate(_SUBSCRIPTS), s)
    s = re.sub(r"\\hat\s*([A-Za-z])", "\\1\u0302", s)
    s = re.sub(r"\\(sin|cos|tan|log|exp|det)\s*(?=[\\A-Za-z])", r"\1 ", s)  # sin θ, not sinθ
    s = re.sub(r"\^([0-9])", lambda m: m.group(1).translate(_SUPERSCRIPTS), s)
    s = re.sub(r"_([0-9])", lambda m: m.group(1).translate(_SUBSCRIPTS), s)

    def command(m: re.Match[str]) -> str:
        name = m.group(1)
        if name in _TEX_DROP:
            return ""
        return _TEX_SYMBOLS.get(name, name)

    s = re.sub(r"\\([A-Za-z]+|.)", command, s)
    s = s.replace("&", "").replace("{", "").replace("}", "").replace("~", " ")
    return " ".join(s.split())


_SEARCH_MATH = re.compile(r"\\\((.+?)\\\)|\\\[(.+?)\\\]|\$\$(.+?)\$\$|\$([^$]+?)\$", re.S)

_SEARCH_CODE = re.compile(r"(<pre>.*?</pre>|<code>.*?</code>)", re.S)

_NOTEBOOK_PROMPT = re.compile(r"(?:In|Out)\xa0\[\d*\]:\s*(?:Copied!\s*)?")


def _math_as_text(m: re.Match[str]) -> str:
    tex = html.unescape(next(g for g in m.groups() if g is not None))
    return html.escape(tex_to_text(tex), quote=False)


def _drop_repeated_code(text: str) -> str:
    """Drop the flattened copy of a code cell that follows its ``<pre>`` in notebook text."""

    def repl(m: re.Match[str]) -> str:
        code, after = m.group(1), m.group(2)
        same = " ".join(after.split()) and " ".join(after.split()) == " ".join(code.split())
        return m.group(0)[: -len(after)] + " " if same else m.group(0)

    return re.sub(r"<pre>(.*?)</pre>([^<]*)", repl, text, flags=re.S)


def readable_search_text(text: str, notebook: bool = False) -> str:
    r"""Search-index text with its math as plain text (code left alone).

    >>> readable_search_text(r"<p>Then \(N = U \times V\).</p> <code>\(x\)</code>")
    '<p>Then N = U × V.</p> <code>\\(x\\)</code>'
    >>> readable_search_text("<pre>a = 1\n</pre> a = 1 <p>next</p>", notebook=True)
    '<pre>a = 1\n</pre> <p>next</p>'
    >>> readable_search_text("<pre>a = 1\n</pre>In\xa0[1]: a = 1 <p>next</p>", notebook=True)
    '<pre>a = 1\n</pre> <p>next</p>'
    """
    parts = _SEARCH_CODE.split(text)  # the even parts are outside code
    if notebook:  # the prompts first: a cell's flattened copy starts with its "In [1]:"
        parts[::2] = [_NOTEBOOK_PROMPT.sub("", part) for part in parts[::2]]
        parts = _SEARCH_CODE.split(_drop_repeated_code("".join(parts)))
    parts[::2] = [_SEARCH_MATH.sub(_math_as_text, part) for part in parts[::2]]
    return "".join(parts)


#: Sections whose code blocks (the API's examples, the notebooks' cells and outputs) are left
#: out of the search index: every page loads the index when it opens, and these blocks would
#: be a third of it. They are found by the words around them and read on their pages.
WORDS_ONLY = ("api/", "notebooks/")

_CODE_BLOCK = re.compile(r"<pre>.*?</pre>", re.S)


def readable_search_index(site_dir: str) -> None:
    """Rewrite the built search index: math as text, no link marks, `WORDS_ONLY` code left out."""
    index = Path(site_dir) / "search" / "search_index.json"
    if index.is_file():
        data = json.loads(index.read_text(encoding="utf-8"))
        for doc in data.get("docs", []):
            location = str(doc.get("location", ""))
            notebook = location.startswith("notebooks/")
            for key in ("title", "text"):
                if isinstance(doc.get(key), str):
                    doc[key] = readable_search_text(doc[key], notebook)
            if location.startswith(WORDS_ONLY) and isinstance(doc.get("text"), str):
                doc["text"] = _CODE_BLOCK.sub(" ", doc["text"])
            if isinstance(doc.get("title"), str):
                doc["title"] = doc["title"].rstrip("¶").rstrip()  # a notebook heading's link mark
        index.write_text(json.dumps(data, ensure_ascii=False), encoding="utf-8")
