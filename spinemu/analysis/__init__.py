"""Analysis of what a chip model records: trace comparison, views, plots, decoders.

This layer reads pin traces and hub dumps; it never reaches into the chip's internals.
"""
