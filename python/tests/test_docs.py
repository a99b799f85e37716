"""The package's docstring examples run and give what they show."""

import doctest

import layered_contact


def test_docstring_examples():
    failures, tried = doctest.testmod(layered_contact)
    assert tried >= 4 and failures == 0
