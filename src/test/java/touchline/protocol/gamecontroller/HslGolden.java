package touchline.protocol.gamecontroller;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * The official HSL golden data in the test resources, and the values its README's tables give
 * for every step file, read from the README itself so the expectations are the official
 * ones, not retyped.
 */
final class HslGolden {

    /** One row of "Files: game fields" (or of the monitor table, where the other fields are -1). */
    record Step(String file, int packetNumber, int stopped, int gamePhase, String state, String setPlay,
                int firstHalf, int kickingTeam, int secsRemaining, int secondaryTime) {
    }

    /** One team cell of "Files: teams". */
    record Team(int number, String colour, String goalkeeperColour, int goalkeeper, int score, int budget) {
    }

    /** One listed player of "Files: teams". */
    record Player(int team, int number, int penalty, String penaltyName, int secs, int warnings, int cautions) {
    }

    private static final Pattern TEAM = Pattern.compile(
            "(\\d+) / (\\d+) (\\w+) / (\\d+) (\\w+) / gk (\\d+) / (\\d+) / (\\d+)");
    private static final Pattern PLAYER = Pattern.compile("team (\\d+) player (\\d+): penalty (\\d+) (\\w+), "
            + "secsTillUnpenalised (\\d+), (?:warnings (\\d+), )?cautions (\\d+)");

    final Path dir;
    final Map<String, Step> steps = new LinkedHashMap<>();
    final Map<String, Step> monitorSteps = new LinkedHashMap<>();
    final Map<String, List<Team>> teams = new LinkedHashMap<>();
    final Map<String, List<Player>> players = new LinkedHashMap<>();
    /** Return packet file to the official parser's verdict ("accepted …" / "rejected: …"). */
    final Map<String, String> returnVerdicts = new LinkedHashMap<>();

    HslGolden(String folder) {
        try {
            dir = Path.of(HslGolden.class.getResource("/golden/gamecontroller/" + folder).toURI());
            for (String line : Files.readAllLines(dir.resolve("README.md"))) {
                row(line);
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
    }

    private void row(String line) {
        if (!line.startsWith("| ") || !line.contains(".bin |")) {
            return;
        }
        String[] c = line.substring(2, line.length() - 2).split(" \\| ", -1);
        String file = c[0].trim();
        if (c.length == 14) {
            steps.put(file, new Step(file, number(c[4]), number(c[5]), number(c[6]), name(c[7]), name(c[8]),
                    number(c[9]), number(c[10]), number(c[11]), number(c[12])));
        } else if (c.length == 6 && file.endsWith(".monitor.bin")) {
            monitorSteps.put(file, new Step(file, -1, -1, -1, name(c[1]), name(c[2]), -1, number(c[3]), number(c[4]),
                    number(c[5])));
        } else if (c.length == 4 && file.matches("r\\d\\d-.*")) {
            returnVerdicts.put(file, c[3].trim());
        } else if (c.length == 4) {
            teams.put(file, List.of(team(c[1]), team(c[2])));
            List<Player> listed = new ArrayList<>();
            Matcher m = PLAYER.matcher(c[3]);
            while (m.find()) {
                listed.add(new Player(Integer.parseInt(m.group(1)), Integer.parseInt(m.group(2)),
                        Integer.parseInt(m.group(3)), m.group(4), Integer.parseInt(m.group(5)),
                        m.group(6) == null ? 0 : Integer.parseInt(m.group(6)), Integer.parseInt(m.group(7))));
            }
            players.put(file, listed);
        }
    }

    private static Team team(String cell) {
        Matcher m = TEAM.matcher(cell.trim());
        if (!m.matches()) {
            throw new IllegalStateException("unexpected team cell: " + cell);
        }
        return new Team(Integer.parseInt(m.group(1)), m.group(3), m.group(5), Integer.parseInt(m.group(6)),
                Integer.parseInt(m.group(7)), Integer.parseInt(m.group(8)));
    }

    private static int number(String cell) {
        return Integer.parseInt(cell.trim().split(" ")[0]);
    }

    private static String name(String cell) {
        return cell.trim().split(" ")[1];
    }

    byte[] bytes(String file) {
        try {
            return Files.readAllBytes(dir.resolve(file));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Every {@code .bin} file directly in the folder (steps and monitor copies). */
    List<String> binFiles() {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".bin") && !n.equals("stream.bin"))
                    .sorted().toList();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** The datagrams of {@code stream.bin}, each {@code size} bytes. */
    List<byte[]> stream(int size) {
        byte[] all = bytes("stream.bin");
        List<byte[]> out = new ArrayList<>();
        for (int at = 0; at + size <= all.length; at += size) {
            out.add(java.util.Arrays.copyOfRange(all, at, at + size));
        }
        if (out.size() * size != all.length) {
            throw new IllegalStateException("stream.bin is not a whole number of datagrams");
        }
        return out;
    }
}
