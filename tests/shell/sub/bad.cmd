sphere in_bad
unknown_thing
sphere after_error
