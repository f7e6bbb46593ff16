"""FeaturePython proxies. Their module paths are stored in saved documents: never move them."""
