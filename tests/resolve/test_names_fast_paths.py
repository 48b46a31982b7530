"""The name validators' regex fast paths give the reasons the per-character scans gave."""
from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from physai_lint.resolve import names


def _isalnum(ch: str) -> bool:
    return ch.isascii() and (ch.isalnum() or ch == "_")


def old_node_name(name: str) -> str | None:
    if not name:
        return "node name must not be empty"
    for i, ch in enumerate(name):
        if not _isalnum(ch):
            return f'node name contains "{ch}" at index {i} (only alphanumerics and "_" are allowed)'
    if name[0].isdigit():
        return "node name must not start with a digit"
    if len(name) > names.NODE_NAME_MAX:
        return f"node name is {len(name)} characters long (at most {names.NODE_NAME_MAX})"
    return None


def old_full_topic(name: str, what: str = "topic name") -> str | None:
    if not name:
        return f"{what} must not be empty"
    if not name.startswith("/"):
        return f"{what} must be absolute (start with \"/\")"
    if name.endswith("/"):
        return f"{what} must not end with \"/\""
    for i, ch in enumerate(name):
        if ch != "/" and not _isalnum(ch):
            return f'{what} contains "{ch}" at index {i} (only alphanumerics, "_" and "/" are allowed)'
    if "//" in name:
        return f'{what} must not contain "//"'
    for token in name.split("/"):
        if token and token[0].isdigit():
            return f'{what} token "{token}" must not start with a digit'
    return None


def old_topic(name: str) -> str | None:
    if not name:
        return "topic name must not be empty"
    if name[0].isdigit():
        return "topic name must not start with a digit"
    if name.endswith("/"):
        return 'topic name must not end with "/"'
    depth = 0
    sub_start = -1
    for i, ch in enumerate(name):
        if ch == "~":
            if i != 0:
                return '"~" is only allowed at the start of a topic name'
            if len(name) > 1 and name[1] != "/":
                return '"~" must be followed by "/"'
            continue
        if ch == "{":
            if depth:
                return "nested \"{\" in topic name"
            depth, sub_start = 1, i
            continue
        if ch == "}":
            if not depth:
                return 'unbalanced "}" in topic name'
            content = name[sub_start + 1 : i]
            if content and content[0].isdigit():
                return f'substitution "{{{content}}}" must not start with a digit'
            depth = 0
            continue
        if ch != "/" and not _isalnum(ch):
            return f'topic name contains "{ch}" at index {i} (only alphanumerics, "_", "/", "~", "{{}}" are allowed)'
        if depth and ch == "/":
            return 'substitution in topic name must not contain "/"'
    if depth:
        return 'unbalanced "{" in topic name'
    for token in name.split("/"):
        if token and token[0].isdigit():
            return f'topic name token "{token}" must not start with a digit'
    return None


NAMES = st.text(alphabet=st.sampled_from(list("ab_Z09/~{}-. é²٣ﬁ")), max_size=12)


@settings(max_examples=2000, deadline=None)
@given(NAMES)
def test_validators_match_the_per_character_scans(name):
    assert names.validate_node_name(name) == old_node_name(name)
    assert names.validate_full_topic_name(name) == old_full_topic(name)
    assert names.validate_full_topic_name(name, "namespace") == old_full_topic(name, "namespace")
    assert names.validate_topic_name(name) == old_topic(name)
