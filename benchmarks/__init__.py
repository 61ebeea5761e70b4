"""Speed comparisons of goldman_lib's hot paths against reference libraries, printed as ratios.

Not part of the test run: ``make bench`` (``python -m benchmarks``) runs the ``main()`` of every
``benchmarks/bench_*.py`` module in turn.  Shared timing helpers are in ``benchmarks.timing``.
"""
