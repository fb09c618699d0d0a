import pytest

from view_support import Bus


def pytest_configure(config):
    config.addinivalue_line("markers", "recorded(CHANNELS): the channels lcm-logger records (a regex)")


@pytest.fixture
def bus(tmp_path, request):
    """The bus, recording the channels the test's `recorded` mark names (not the images: GBs)."""
    b = Bus(tmp_path, request.node.get_closest_marker("recorded").args[0])
    yield b
    b.stop()
