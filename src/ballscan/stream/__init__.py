"""Continuous line streams: the chunked engine, line sources and batches of recordings."""
