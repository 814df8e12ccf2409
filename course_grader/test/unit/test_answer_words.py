"""A rotate answer read as a teaching assistant reads it (issue 31): success in the
student's own words, misspelt or not, a bool field's value rather than its name."""
import pytest
from std_srvs.srv import SetBoolResponse, TriggerResponse

from course_grader.answer_words import answer_text, claims_success
from course_grader.measures import Rotation


@pytest.mark.parametrize("text", [
    "success: rotated -90 degrees (final error 0.3 degrees)", "Rotation completed", "true",
    "Rotation succesfully done", "Sucessfully rotated", "successfull", "Done!", "OK",
    "Rotated -90 degrees", "The robot has completed the rotation", "Rotation finished",
    "Target reached", "yes", "SUCCESS"])
def test_what_a_ta_reads_as_success(text):
    assert claims_success(text)


@pytest.mark.parametrize("text", [
    "failure: blocked", "false", "Rotation failed", "error: no odometry", "Rotation not completed",
    "could not rotate", "Couldn't rotate", "timed out after 20 s", "unsuccessful",
    "success: false", "done with errors", "aborted", "", "rotating...", "request received",
    "Invalid angle", "The rotation has not been successful"])
def test_what_a_ta_reads_as_no_success(text):
    assert not claims_success(text)


def test_a_bool_field_answers_in_its_value_not_its_name():
    assert answer_text(SetBoolResponse(success=True, message="")) == "true"
    assert answer_text(SetBoolResponse(success=False, message="rotation done")) == \
        "false rotation done"
    assert not claims_success(answer_text(SetBoolResponse(success=False, message="done")))
    assert claims_success(answer_text(TriggerResponse(success=True,
                                                      message="Rotation completed")))


def test_the_rotate_item_accepts_the_students_words():
    for words in ("Rotation completed", "true", "Rotation succesfully done"):
        assert Rotation(-90, -89.6, words, answered_at=5.0, stopped_at=4.9).answered_when_done(
            0.25, 30), words
