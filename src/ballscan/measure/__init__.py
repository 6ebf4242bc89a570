"""What an image shows: loading, detection of balls against the background, sub-pixel edges (window and matched), the columns' gains, the ball's shading, and the robust statistics they share."""
