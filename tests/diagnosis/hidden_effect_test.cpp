// hidden-effect tests (filled below)
