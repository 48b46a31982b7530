"""A deterministic layered layout (Sugiyama-style) for the HTML graph picture.

Data flows left to right: a publisher sits left of its topic, the topic left of its subscribers, a
container left of the components it loads. Cycles (a controller loop) are broken by reversing DFS
back edges for layering only. Within a column the vertices of one namespace stay together so the
picture can draw the namespace as a box; a few barycenter sweeps reduce edge crossings. Pure
Python, no randomness: the same graph always gets the same picture.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

BOX_H = 30
V_GAP = 12
GROUP_GAP = 18
HEADER_H = 22
COL_GAP = 110
MARGIN = 30
CHAR_W = 7.4
SWEEPS = 6
H_GAP = 14
ROW_GAP = 60
ASPECT = 1.6  # a landscape screen: pick the orientation whose picture is closest to it


@dataclass(frozen=True)
class LVertex:
    id: str
    label: str
    group: str | None  # namespace cluster; None for vertices outside clusters (topics)
    extra: str = ""  # text drawn after the label (e.g. "no publisher"); counts for the width


@dataclass(frozen=True)
class Box:
    id: str
    x: float
    y: float
    w: float
    h: float
    layer: int


@dataclass(frozen=True)
class Cluster:
    name: str
    x: float
    y: float
    w: float
    h: float


@dataclass
class Layout:
    boxes: dict[str, Box]
    clusters: list[Cluster]
    width: float
    height: float
    vertical: bool  # data flows top to bottom (else left to right)


def box_width(v: LVertex) -> float:
    chars = len(v.label) + (len(v.extra) + 2 if v.extra else 0)
    return max(110.0, round(chars * CHAR_W + 24))


def _acyclic(order: list[str], succ: dict[str, list[str]]) -> dict[str, list[str]]:
    """Successor lists with DFS back edges reversed (iterative DFS in ``order``)."""
    state: dict[str, int] = {}  # 1 on stack, 2 done
    dag: dict[str, list[str]] = {v: [] for v in order}
    for root in order:
        if root in state:
            continue
        state[root] = 1
        stack = [(root, iter(succ[root]))]
        while stack:
            v, it = stack[-1]
            nxt = next(it, None)
            if nxt is None:
                state[v] = 2
                stack.pop()
            elif state.get(nxt) == 1:
                dag[nxt].append(v)  # back edge: reversed
            else:
                dag[v].append(nxt)
                if nxt not in state:
                    state[nxt] = 1
                    stack.append((nxt, iter(succ[nxt])))
    return dag


def _layers(order: list[str], dag: dict[str, list[str]]) -> dict[str, int]:
    pred: dict[str, list[str]] = {v: [] for v in order}
    for v in order:
        for w in dag[v]:
            pred[w].append(v)
    layer: dict[str, int] = {}
    indeg = {v: len(set(pred[v])) for v in order}
    ready = [v for v in order if indeg[v] == 0]
    seen_pairs: set[tuple[str, str]] = set()
    while ready:
        v = ready.pop(0)
        layer.setdefault(v, 0)
        for w in dag[v]:
            if (v, w) in seen_pairs:
                continue
            seen_pairs.add((v, w))
            layer[w] = max(layer.get(w, 0), layer[v] + 1)
            indeg[w] -= 1
            if indeg[w] == 0:
                ready.append(w)
    for v in order:  # unreachable only if the DAG were cyclic; keep every vertex placed
        layer.setdefault(v, 0)
    # sources move right next to their nearest successor: shorter edges
    for v in order:
        if not pred[v] and dag[v]:
            layer[v] = max(0, min(layer[w] for w in dag[v]) - 1)
    return layer


def _sort_layer(verts: list[str], bary: dict[str, float], groups: dict[str, str | None]) -> list[str]:
    """Keep each namespace contiguous: order groups by their mean barycenter, members by theirs."""
    members: dict[str, list[str]] = {}
    for i, v in enumerate(verts):
        key = f"g:{groups[v]}" if groups[v] is not None else f"v:{v}"
        members.setdefault(key, []).append(v)
    pos = {v: i for i, v in enumerate(verts)}

    def b(v: str) -> float:
        return bary.get(v, float(pos[v]))

    keyed = sorted(members.items(), key=lambda kv: (sum(b(v) for v in kv[1]) / len(kv[1]), kv[0]))
    return [v for _, vs in keyed for v in sorted(vs, key=lambda v: (b(v), pos[v]))]


def layout(vertices: list[LVertex], edges: list[tuple[str, str]]) -> Layout:
    """Place ``vertices`` (in a stable input order) given directed ``edges`` between their ids."""
    order = [v.id for v in vertices]
    by_id = {v.id: v for v in vertices}
    succ: dict[str, list[str]] = {v: [] for v in order}
    for a, b in edges:
        if a in succ and b in succ and a != b and b not in succ[a]:
            succ[a].append(b)
    has_pred = {b for a in order for b in succ[a]}
    roots = [v for v in order if v not in has_pred] + [v for v in order if v in has_pred]
    layer = _layers(order, _acyclic(roots, succ))

    n_layers = max(layer.values(), default=0) + 1
    cols: list[list[str]] = [[] for _ in range(n_layers)]
    groups = {v.id: v.group for v in vertices}
    for v in order:
        cols[layer[v]].append(v)
    cols = [_sort_layer(c, {}, groups) for c in cols]

    nbrs_left: dict[str, list[str]] = {v: [] for v in order}
    nbrs_right: dict[str, list[str]] = {v: [] for v in order}
    for a in order:
        for b in succ[a]:
            lo, hi = (a, b) if layer[a] < layer[b] else (b, a)
            if layer[lo] != layer[hi]:
                nbrs_right[lo].append(hi)
                nbrs_left[hi].append(lo)
    for sweep in range(SWEEPS):
        rank = {v: i for c in cols for i, v in enumerate(c)}
        seq = range(1, n_layers) if sweep % 2 == 0 else range(n_layers - 2, -1, -1)
        for li in seq:
            nb = nbrs_left if sweep % 2 == 0 else nbrs_right
            bary = {v: sum(rank[u] for u in nb[v]) / len(nb[v]) for v in cols[li] if nb[v]}
            cols[li] = _sort_layer(cols[li], bary, groups)
            rank.update({v: i for i, v in enumerate(cols[li])})

    widths = {v: box_width(by_id[v]) for v in order}
    lr = _place_lr(cols, groups, widths)
    tb = _place_tb(cols, groups, widths)
    return min((lr, tb), key=lambda lay: abs(math.log(lay.width / lay.height / ASPECT)))


def _runs(col: list[str], groups: dict[str, str | None]) -> list[tuple[str | None, list[str]]]:
    """Consecutive vertices of one namespace (topics: one run each)."""
    out: list[tuple[str | None, list[str]]] = []
    for v in col:
        g = groups[v]
        if out and g is not None and out[-1][0] == g:
            out[-1][1].append(v)
        else:
            out.append((g, [v]))
    return out


def _place_lr(cols: list[list[str]], groups: dict[str, str | None], widths: dict[str, float]) -> Layout:
    boxes: dict[str, Box] = {}
    clusters: list[Cluster] = []
    x, height = float(MARGIN), 0.0
    for li, col in enumerate(cols):
        col_w = max((widths[v] for v in col), default=110.0)
        y = float(MARGIN)
        for g, run in _runs(col, groups):
            top = y
            if g is not None:
                y += HEADER_H
            for v in run:
                boxes[v] = Box(v, x, y, widths[v], BOX_H, li)
                y += BOX_H + V_GAP
            if g is not None:
                clusters.append(Cluster(g, x - 10, top - 4, col_w + 20, y - top))
                y += GROUP_GAP - V_GAP
        height = max(height, y)
        x += col_w + COL_GAP
    return Layout(boxes, clusters, x - COL_GAP + MARGIN, height + MARGIN, vertical=False)


def _place_tb(cols: list[list[str]], groups: dict[str, str | None], widths: dict[str, float]) -> Layout:
    boxes: dict[str, Box] = {}
    clusters: list[Cluster] = []
    y, width = float(MARGIN), 0.0
    for li, row in enumerate(cols):
        x = float(MARGIN)
        for g, run in _runs(row, groups):
            left = x
            if g is not None:
                x += 10
            for v in run:
                boxes[v] = Box(v, x, y + HEADER_H, widths[v], BOX_H, li)
                x += widths[v] + H_GAP
            if g is not None:
                x += 10 - H_GAP
                label_w = len(g) * CHAR_W + 20
                x = max(x, left + label_w)
                clusters.append(Cluster(g, left, y, x - left, HEADER_H + BOX_H + 8))
                x += H_GAP
        width = max(width, x)
        y += HEADER_H + BOX_H + ROW_GAP
    return Layout(boxes, clusters, width - H_GAP + MARGIN, y - ROW_GAP + MARGIN + 8, vertical=True)
