"""Forward models of the ball's image: the analytic silhouette per line and the independent supersampled renderer."""
