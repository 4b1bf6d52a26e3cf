"""playground: a 2D game-physics playground for force-driven player bodies."""
