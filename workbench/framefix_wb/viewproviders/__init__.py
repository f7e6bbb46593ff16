"""View providers. Their module paths are stored in saved documents: never move them."""
