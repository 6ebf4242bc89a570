"""The camera and the ball's motion: the line-scan camera model (the paper's Eq. (1)), its lens and pose, and the dynamic sphere of Eq. (8)."""
