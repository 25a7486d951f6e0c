"""Values of a run's manifest.json `results`, shared by the plot scripts."""


def lookup(results, dotted):
    """A manifest results value by dotted name (nested maps), or None."""
    node = results
    for part in dotted.split("."):
        if not isinstance(node, dict) or part not in node:
            return None
        node = node[part]
    return float(node) if isinstance(node, (int, float)) else None
