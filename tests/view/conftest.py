def pytest_configure(config):
    config.addinivalue_line("markers", "recorded(CHANNELS): the channels lcm-logger records (a regex)")
