package touchline.cli;

import touchline.app.game.MatchMode;

import java.io.PrintWriter;

/**
 * The terminal's view of a console's first listen (match mode holds robot traffic until a
 * GameController is heard or {@link MatchMode#LISTEN_FIRST_MS} have passed): one line when the
 * command starts waiting, one when the wait ends and why.
 */
final class FirstListenLines {

    private final PrintWriter out;
    private final String command;

    FirstListenLines(PrintWriter out, String command) {
        this.out = out;
        this.command = command;
    }

    /** Prints the waiting line when {@code matchMode} still listens, and the end line when it ends. */
    void follow(MatchMode matchMode) {
        if (matchMode.listeningFirst()) {
            say("match mode: " + matchMode.play());
        }
        matchMode.onListenEnd(why -> say("match mode: " + why));
    }

    private void say(String line) {
        synchronized (out) {
            out.println("touchline " + command + ": " + line);
            out.flush();
        }
    }
}
