"""What a service's answer says, read as a teaching assistant reads it: whether it claims
the job was done, in the student's own words.

The guide asks for "a message indicating the rotation has been successful": ``success``,
``Rotation completed``, ``done``, ``true``, ``Rotated -90 degrees`` and a misspelt
``Rotation succesfully done`` all say so; ``failure``, ``error``, ``false``, ``could not
rotate``, ``not completed``, ``unsuccessful`` say it was not. A word of failure outweighs a
word of success (``success: false``, ``done with errors``). No ROS here."""
from __future__ import annotations

import re

# words of success and completion, with the misspellings students write (succes, sucess,
# succesfull, successfull, succesfully, sucessfully)
SUCCESS = re.compile(r"\b(?:su?c{1,2}es{1,2}\w*|succeed\w*|complete[ds]?|done|finished|"
                     r"reached|rotated|turned|ok|okay|true|yes)\b", re.IGNORECASE)
# words of failure; "not" only before a word of success (a success message may say "not"),
# "error" not before a figure ("final error 0.3 degrees" measures a success)
FAILURE = re.compile(r"\b(?:fail\w*|errors?\b(?!\s*(?:of|was|is|[:=])?\s*[-+]?\.?\d)|abort\w*|"
                     r"unable|cannot|can't|could\s*n[o']t|"
                     r"false|timed?\s*out|refused|rejected|invalid|unsuccessful\w*|"
                     r"(?:not|never)\s+(?:been\s+|be\s+)?(?:su?c{1,2}es{1,2}\w*|succeed\w*|"
                     r"complete[ds]?|done|finished|reached|rotated|turned))\b", re.IGNORECASE)


def claims_success(text: str) -> bool:
    """The answer says the job was done: a word of success and none of failure."""
    return bool(SUCCESS.search(text)) and not FAILURE.search(text)


def answer_text(response) -> str:
    """A service response as words: its string fields as written, its bool fields as
    ``true``/``false`` (a ``bool success`` field answers in its value, not its name), other
    fields left out; a response with none of those, as rospy prints it."""
    if response is None:
        return ""
    words = []
    for name, kind in zip(getattr(response, "__slots__", ()),
                          getattr(response, "_slot_types", ())):
        value = getattr(response, name)
        if kind == "string":
            words.append(str(value))
        elif kind == "bool":
            words.append("true" if value else "false")
    return " ".join(w for w in words if w) if words else str(response)
