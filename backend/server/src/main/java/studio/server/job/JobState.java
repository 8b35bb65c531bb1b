package studio.server.job;

import com.fasterxml.jackson.annotation.JsonValue;

/** Where a render job is in its life; the last three are final. */
public enum JobState {
    QUEUED, RUNNING, DONE, FAILED, CANCELLED;

    public boolean isFinal() {
        return this == DONE || this == FAILED || this == CANCELLED;
    }

    /** The state as the API writes it: lower case. */
    @JsonValue
    public String json() {
        return name().toLowerCase();
    }
}
