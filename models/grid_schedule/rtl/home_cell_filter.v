// The one-cell filter (docs/grid_board.md, "Reporting each pair once"): of
// the lane hits in the cell being swept, keeps those whose pair has its
// overlap's lower corner here: on every axis the row's box or the column's
// box starts in this cell. Each box's first cell per axis comes from the cell
// buffer beside its coordinates; three pairs of byte equalities a lane, the
// row's shared by every lane. Combinational, between the lanes and the pair
// FIFO. Cells are packed x, y, z, a byte each, lowest first.
module home_cell_filter #(
    parameter LANES = 15
) (
    input  wire [LANES-1:0]    hits,
    input  wire [23:0]         here,          // the swept cell
    input  wire [23:0]         row_first,     // port 0's box's first cells
    input  wire [LANES*24-1:0] column_first,  // lane k's column box's first cells
    output wire [LANES-1:0]    kept
);
    wire [2:0] row_here;
    genvar a, k;
    generate
        for (a = 0; a < 3; a = a + 1) begin : g_row
            assign row_here[a] = row_first[a*8 +: 8] == here[a*8 +: 8];
        end
        for (k = 0; k < LANES; k = k + 1) begin : g_lane
            wire [2:0] here_on;
            for (a = 0; a < 3; a = a + 1) begin : g_axis
                assign here_on[a] = row_here[a] | (column_first[k*24 + a*8 +: 8] == here[a*8 +: 8]);
            end
            assign kept[k] = hits[k] & (&here_on);
        end
    endgenerate
endmodule
