"""What an image shows: loading, detection of balls against the background, sub-pixel edges, the columns' gains and the ball's shading."""
