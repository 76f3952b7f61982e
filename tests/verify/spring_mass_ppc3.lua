-- Verification case (issue 30 item 1): the spring-mass with the string's
-- points a third of a cell apart. Period and static deflection derived in
-- lib/spring_mass.lua.
-- verify: membrane
require("lib.spring_mass").run(3)
