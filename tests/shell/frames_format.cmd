# frames_format: a third format is an error naming the two
frames_format = gif
frames_format = png
frames_format = ppm
help frames_format
