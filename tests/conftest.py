"""Settings shared by every test: Hypothesis judges the code, never the machine's load.

`make test` runs the unit tests on every core beside other work; a property test must fail
only when a property fails, so no per-example deadline and no "input generation is slow"
health check (the number of examples each test draws is unchanged).
"""

from hypothesis import HealthCheck, settings

settings.register_profile(
    "trinormal",
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)
settings.load_profile("trinormal")
