"""The typed, position-carrying model: spans, values, the launch IR and findings."""
